# Dimples as a height: spherical hollows of radius period/2, cut off where their slope
# matches the seed's (r2 > 100 for period 30), so the gradient equals the seed's
# Bu = iu / sqrt(r2) without its integer steps.
param period = 30 in 4..300
param depth = 1 in 0..4   # 1 = the seed's spherical dimples (5 units deep at period 30)

let half = period / 2
let rim = period / 3
let cu = u % period - half
let cv = v % period - half
let cap = half^2 - cu^2 - cv^2
height = if cap > rim^2 then depth * (rim - sqrt(cap)) else 0
