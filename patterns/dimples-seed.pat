# The seed lecture's own dimples ("Bump Map Code – Dimples"), in slope form. The seed's C:
#   iu = (int)uu % 30 - 15;  iv = (int)vv % 30 - 15;
#   r2 = 225.0 - iu*iu - iv*iv;
#   if (r2 > 100) { Bu = iu == 0 ? 0 : iu / sqrt(r2);  Bv = iv == 0 ? 0 : iv / sqrt(r2); }
# One change: `%` here is floored, so the grid carries on across u = 0 and v = 0
# (C's `%` mirrors it there).
param strength = 1 in 0..4   # 1 = the seed

let iu = floor(u) % 30 - 15
let iv = floor(v) % 30 - 15
let r2 = 225 - iu * iu - iv * iv
let inside = r2 > 100
slope = (if inside and iu != 0 then strength * iu / sqrt(r2) else 0,
         if inside and iv != 0 then strength * iv / sqrt(r2) else 0)
