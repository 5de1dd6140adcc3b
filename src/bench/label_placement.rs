//! Where the chart's number labels go: beside their dots, each moved to the first free place
//! around its dot so no two labels overlap, however close the dots are.

/// A label's box: left, top, width, height, in pixels.
pub type LabelBox = (f32, f32, f32, f32);

/// Gap between a dot and its label, and between rings of further-out places.
const GAP: f32 = 6.0;
/// Space kept clear around a placed label, so neighbouring numbers do not read as one.
const PAD: f32 = 7.0;
/// Half the side of the square a dot takes, which labels keep clear of too.
const DOT: f32 = 4.0;
/// Rings of places tried around a dot before the least crowded one is taken.
const RINGS: usize = 6;

/// The top-left corner of each label of `sizes` (width, height) for the dot at the same index of
/// `anchors`, placed in order: the first of the places around the dot (right and up first, as a
/// reader expects) whose box, with `PAD` around it, overlaps no dot and no label placed before.
pub fn place_labels(anchors: &[(f32, f32)], sizes: &[(f32, f32)]) -> Vec<(f32, f32)> {
    let dots: Vec<LabelBox> = anchors
        .iter()
        .map(|&(x, y)| (x - DOT, y - DOT, 2.0 * DOT, 2.0 * DOT))
        .collect();
    let mut placed: Vec<LabelBox> = Vec::with_capacity(anchors.len());
    for (&(x, y), &(w, h)) in anchors.iter().zip(sizes) {
        let candidates = candidates((x, y), (w, h));
        let crowds = |(left, top): (f32, f32)| {
            let padded = (left - PAD, top - PAD, w + 2.0 * PAD, h + 2.0 * PAD);
            crowding(padded, &placed) + crowding((left, top, w, h), &dots)
        };
        let free = candidates.iter().find(|&&spot| crowds(spot) == 0);
        let (left, top) = match free {
            Some(&spot) => spot,
            None => *candidates
                .iter()
                .min_by_key(|&&spot| crowds(spot))
                .expect("candidates"),
        };
        placed.push((left, top, w, h));
    }
    placed
        .iter()
        .map(|&(left, top, _, _)| (left, top))
        .collect()
}

/// Places around the dot at `(x, y)`, nearest first: right-up, right-down, left-up, left-down,
/// above, below, then the same further out.
fn candidates((x, y): (f32, f32), (w, h): (f32, f32)) -> Vec<(f32, f32)> {
    (0..RINGS)
        .flat_map(|ring| {
            let d = GAP + ring as f32 * (h + GAP);
            [
                (x + d, y - h - d / 2.0),
                (x + d, y + d / 2.0),
                (x - w - d, y - h - d / 2.0),
                (x - w - d, y + d / 2.0),
                (x - w / 2.0, y - h - d),
                (x - w / 2.0, y + d),
            ]
        })
        .collect()
}

fn overlaps(a: LabelBox, b: LabelBox) -> bool {
    a.0 < b.0 + b.2 && b.0 < a.0 + a.2 && a.1 < b.1 + b.3 && b.1 < a.1 + a.3
}

/// How many placed boxes `candidate` overlaps.
fn crowding(candidate: LabelBox, placed: &[LabelBox]) -> usize {
    placed.iter().filter(|b| overlaps(candidate, **b)).count()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_lone_label_sits_right_of_its_dot_and_above() {
        let spots = place_labels(&[(100.0, 100.0)], &[(20.0, 14.0)]);
        assert_eq!(spots, vec![(106.0, 83.0)]);
        assert!(
            !overlaps((106.0, 83.0, 20.0, 14.0), (96.0, 96.0, 8.0, 8.0)),
            "clear of its dot"
        );
    }

    #[test]
    fn labels_of_dots_in_a_cluster_never_overlap() {
        // 24 dots within 30 pixels, as the bench's variants of one scene crowd together.
        let anchors: Vec<(f32, f32)> = (0..24)
            .map(|i| (200.0 + (i % 6) as f32 * 5.0, 200.0 + (i / 6) as f32 * 7.0))
            .collect();
        let sizes: Vec<(f32, f32)> = (0..24)
            .map(|i| (if i < 9 { 10.0 } else { 22.0 }, 14.0))
            .collect();
        let spots = place_labels(&anchors, &sizes);
        for i in 0..spots.len() {
            for j in 0..i {
                let a = (spots[i].0, spots[i].1, sizes[i].0, sizes[i].1);
                let b = (spots[j].0, spots[j].1, sizes[j].0, sizes[j].1);
                let padded = (a.0 - PAD, a.1 - PAD, a.2 + 2.0 * PAD, a.3 + 2.0 * PAD);
                assert!(
                    !overlaps(padded, b),
                    "labels {i} and {j} touch: {a:?} {b:?}"
                );
            }
        }
    }
}
