# Bark: long ridges and furrows, ridged gradient noise stretched along v, with a fine grain
# of fbm over it.
param scale = 14 in 1..200      # width of a ridge, in (u, v) units
param stretch = 8 in 1..40      # how much longer than wide a ridge is
param depth = 6 in 0..50
param grain = 0.2 in 0..1       # the fine grain's share of the depth

let ridge = 1 - abs(perlin(u / scale, v / (scale * stretch)))
let fine = fbm(u / 6, v / 24, 3)
height = depth * (ridge^3 + grain * fine)
