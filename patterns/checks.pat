# Cyan and magenta checks (seed: "Cyan and Magenta Checks"), with a floored `%`, so the
# squares keep their size across x = 0 and y = 0.
param period = 50 in 1..1000

let cyan = rgb(0, 1, 1)
let magenta = rgb(1, 0, 1)
let low_x = x % period < period / 2
let low_y = y % period < period / 2
color = if (low_x and low_y) or (not low_x and not low_y) then cyan else magenta
