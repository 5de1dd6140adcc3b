# Squares: raised square tiles with bevelled edges (seed: "Plane with Squares").
param period = 40 in 4..400
param size = 26 in 1..400     # side of each square
param bevel = 3 in 0.01..100  # width of the sloping edge
param raise = 3 in 0..50

let cu = abs(u % period - period / 2)
let cv = abs(v % period - period / 2)
let inside = size / 2 - max(cu, cv)   # distance inside the square's edge
height = raise * clamp(inside / bevel, 0, 1)
