# Stucco: a plastered wall's irregular lumps, a fractal sum of gradient noise (fbm) whose
# crests are flattened where the trowel passed.
param scale = 40 in 2..400      # size of the largest lumps, in (u, v) units
param depth = 4 in 0..50
param octaves = 5 in 1..10      # finer detail with each octave, each half as high
param flatten = 0.35 in 0..1    # crests above this are smoothed off

let lumps = fbm(u / scale, v / scale, octaves)
let crest = flatten - 0.2 * smoothstep(flatten - 0.3, flatten + 0.3, lumps)
height = depth * min(lumps, crest + 0.2 * lumps)
