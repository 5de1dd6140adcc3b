# Cyan and magenta checks (seed: "Cyan and Magenta Checks"), with a floored `%`, so the
# squares keep their size across 0. Solid checks: z joins x and y, so a plane parallel to any
# coordinate plane shows squares (with x and y alone a floor, where y is constant, showed
# stripes); where z = 0 the colours are the seed's.
param period = 50 in 1..1000

let cyan = rgb(0, 1, 1)
let magenta = rgb(1, 0, 1)
let low_x = x % period < period / 2
let low_y = y % period < period / 2
let low_z = z % period < period / 2
# The seed's "both low or both high", as equality of conditions.
let same_xy = low_x == low_y
color = if same_xy == low_z then cyan else magenta
