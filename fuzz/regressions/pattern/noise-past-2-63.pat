height = noise(u, v) + noise(x, y, z)
