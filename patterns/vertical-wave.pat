# Vertical wave: crests run along v, so the surface rises and falls with u
# (seed: "Plane with Vertical Wave").
param wavelength = 40 in 2..400
param amplitude = 3 in 0..50
param speed = 0 in -100..100   # units per second the crests travel; 0 = still

height = amplitude * sin(2 * pi * (u - speed * t) / wavelength)
