# Spheres: a grid of hemispherical bumps (seed: "Plane with Spheres").
# Units are the seed's: u, v in 0..400 on the plane, 0..720 x 0..360 on a sphere.
param period = 30 in 4..300   # distance between bump centres
param radius = 12 in 1..150   # bump radius; below period / 2 leaves flat gaps
param scale = 1 in 0..4       # 1 = true hemispheres, smaller flattens them

let cu = u % period - period / 2
let cv = v % period - period / 2
height = scale * sqrt(max(0, radius^2 - cu^2 - cv^2))
