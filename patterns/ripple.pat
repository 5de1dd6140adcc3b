# Ripple: concentric rings around one centre (seed: "Plane with Ripple").
param centre_u = 200 in -1000..1000
param centre_v = 200 in -1000..1000
param wavelength = 25 in 2..400
param amplitude = 2 in 0..50
param speed = 0 in -100..100   # units per second the rings move outwards

let r = hypot(u - centre_u, v - centre_v)
# cos, not sin: flat at the centre instead of a cone point.
height = amplitude * cos(2 * pi * (r - speed * t) / wavelength)
