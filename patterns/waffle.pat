# Waffle: a square pocket in every cell, deepest in the middle, with ridges on the grid
# lines (seed: "Plane with Waffle").
param period = 40 in 4..400
param depth = 4 in 0..50

let su = sin(pi * (u % period) / period)
let sv = sin(pi * (v % period) / period)
height = -depth * su * sv
