# Hexagons: hexagonal tiles with sunken grooves between them.
param size = 30 in 2..1000     # distance between neighbouring tile centres
param groove = 3 in 0.1..100   # groove width
param bevel = 2 in 0.01..100   # width of the sloping tile edge
param depth = 2 in 0..50       # groove depth

# Tile centres form two rectangular lattices offset by half a cell; the nearer
# lattice point is this tile's centre.
let root3 = sqrt(3)
let pu = u / size
let pv = v / size
let au = pu % 1 - 0.5
let av = pv % root3 - root3 / 2
let bu = (pu - 0.5) % 1 - 0.5
let bv = (pv - root3 / 2) % root3 - root3 / 2
let near_a = au^2 + av^2 < bu^2 + bv^2
let gu = abs(if near_a then au else bu)
let gv = abs(if near_a then av else bv)
# 0.5 on the tile's edge
let hex_radius = max(0.5 * gu + root3 / 2 * gv, gu)
let edge = (0.5 - hex_radius) * size - groove / 2
height = depth * (clamp(edge / bevel, 0, 1) - 1)
