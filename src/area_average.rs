//! Area averaging (a box filter) from one grid size to another along one axis: each destination
//! cell averages the source cells it covers, weighted by how much of each it covers. Mip levels
//! and the workbench's pictures of another size are made with it.

/// For each of `destination` cells, the source cells it covers and their weights, summing to 1:
/// destination `d` spans source `[d·r, (d+1)·r)` with `r = source / destination`. None where the
/// source is empty.
pub fn area_weights(source: usize, destination: usize) -> Vec<Vec<(usize, f32)>> {
    if source == 0 {
        return vec![Vec::new(); destination];
    }
    let scale = source as f64 / destination as f64;
    (0..destination)
        .map(|d| {
            let (start, end) = (d as f64 * scale, (d + 1) as f64 * scale);
            let first = start.floor() as usize;
            let last = (end.ceil() as usize).clamp(first + 1, source);
            (first..last)
                .map(|s| {
                    let overlap = (end.min(s as f64 + 1.0) - start.max(s as f64)).max(0.0);
                    (s, (overlap / scale) as f32)
                })
                .filter(|&(_, w)| w > 0.0)
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_cover_each_destination_exactly_once() {
        let cases = [
            (4, 3),
            (4, 2),
            (3, 3),
            (7, 5),
            (2, 5),
            (2, 1),
            (3, 1),
            (9, 4),
            (1, 1),
        ];
        for (source, destination) in cases {
            let weights = area_weights(source, destination);
            assert_eq!(weights.len(), destination);
            for cell in &weights {
                let sum: f32 = cell.iter().map(|&(_, w)| w).sum();
                assert!(
                    (sum - 1.0).abs() < 1e-5,
                    "{source}->{destination}: {cell:?}"
                );
            }
            // Every source cell is covered in all, once over: its weights sum to d / s.
            let mut coverage = vec![0.0f32; source];
            for &(s, w) in weights.iter().flatten() {
                coverage[s] += w;
            }
            let each = destination as f32 / source as f32;
            assert!(
                coverage.iter().all(|c| (c - each).abs() < 1e-5),
                "{coverage:?}"
            );
        }
    }

    #[test]
    fn an_empty_source_gives_no_weights() {
        assert_eq!(area_weights(0, 3), vec![Vec::new(); 3]);
    }
}
