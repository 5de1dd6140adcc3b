# Dots and dimples: round bumps and hollows alternating like a checkerboard
# (seed: "Dots and Dimples").
param period = 30 in 4..300
param radius = 11 in 1..150
param depth = 4 in 0..50

let cu = u % period - period / 2
let cv = v % period - period / 2
# a dome (1 - r²/R²)², smooth where it meets the flat
let dome = depth * max(0, 1 - (cu^2 + cv^2) / radius^2)^2
let dot_cell = (floor(u / period) + floor(v / period)) % 2 < 0.5
height = if dot_cell then dome else -dome
