# Ripples: rings from three centres, fading with distance, adding where they cross
# (seed: "Plane with Ripples").
param wavelength = 20 in 2..400
param amplitude = 3 in 0..50
param decay = 120 in 1..10000   # distance over which rings fade to 1/e
param speed = 0 in -100..100    # units per second the rings move outwards

let k = 2 * pi / wavelength
let phase = speed * t
let r1 = hypot(u - 120, v - 140)
let r2 = hypot(u - 280, v - 120)
let r3 = hypot(u - 200, v - 290)
let ring1 = cos(k * (r1 - phase)) * exp(-r1 / decay)
let ring2 = cos(k * (r2 - phase)) * exp(-r2 / decay)
let ring3 = cos(k * (r3 - phase)) * exp(-r3 / decay)
height = amplitude * (ring1 + ring2 + ring3)
