# Mesh: raised grid lines with rounded edges (seed: "Plane with Mesh").
param period = 40 in 4..400
param width = 6 in 0.5..200   # line width
param soft = 1.5 in 0.01..20  # half-width of the rounded edge
param raise = 3 in 0..50

# distance to the nearest line (lines at multiples of the period)
let du = abs((u + period / 2) % period - period / 2)
let dv = abs((v + period / 2) % period - period / 2)
let line_u = 1 - smoothstep(width / 2 - soft, width / 2 + soft, du)
let line_v = 1 - smoothstep(width / 2 - soft, width / 2 + soft, dv)
height = raise * max(line_u, line_v)
