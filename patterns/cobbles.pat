# Cobbles: rounded stones set in mortar, one in each cell of a jittered lattice, from the
# distance to the nearest cell point (cellular noise).
param size = 48 in 4..300       # spacing of the stones, in (u, v) units
param radius = 0.48 in 0.2..1   # a stone's radius, as a fraction of the spacing
param rise = 5 in 0..50       # a stone's height above the mortar
param speed = 0 in -10..10      # stones per second the pattern drifts along u

let d = cells(u / size - speed * t, v / size)
let cap = clamp(1 - (d / radius)^2, 0, 1)
height = rise * cap * (2 - cap)
