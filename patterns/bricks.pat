# Bricks: courses of bricks offset by half a brick, with sunken mortar joints.
param brick = 60 in 2..1000    # brick length along u
param course = 25 in 1..1000   # brick height along v
param mortar = 4 in 0.1..50    # joint width
param bevel = 2 in 0.01..50    # width of the rounded brick edge
param depth = 2 in 0..50       # how far the joints are sunk

let row = floor(v / course)
let shift = (row % 2) * brick / 2   # every other course is offset by half a brick
let bu = (u + shift) % brick
let bv = v % course
let edge = min(min(bu, brick - bu), min(bv, course - bv)) - mortar / 2
height = depth * (clamp(edge / bevel, 0, 1) - 1)
