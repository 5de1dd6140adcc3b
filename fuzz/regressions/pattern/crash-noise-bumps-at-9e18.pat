# Bumps: irregular lumps from value noise of the object-space point, like POV-Ray's
# `bumps`. Follows the object, not the (u, v) map, so it has no seams or pole pinching.
param scale = 20 in 0.1..1000   # feature size in object units
param amount = 3 in 0..50
param detail = 0.5 in 0..1      # weight of the second, finer octave

let px = x / scale
let py = y / scale
let pz = z / scale
let coarse = noise(px, py, pz)
let fine = noise(2 * px + 17.3, 2 * py - 4.1, 2 * pz + 9.2)
height = amount * (coarse + detail * fine)
