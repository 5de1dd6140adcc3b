# Red and blue stripes (seed: "if ((x % 50) < 25) color = red else color = blue"), with a
# floored `%`, so the stripes keep their width across x = 0.
param period = 50 in 1..1000

let red = rgb(1, 0, 0)
let blue = rgb(0, 0, 1)
color = if x % period < period / 2 then red else blue
