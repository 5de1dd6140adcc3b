//! Writing stills.

mod stills;
