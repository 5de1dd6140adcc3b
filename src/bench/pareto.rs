//! The Pareto front of cost against error: the settings that nothing beats on both.

/// Indices of the points (cost, error), both to be minimised, that no other point dominates
/// (no other is at most as costly and at most as wrong, and better in one), by rising cost.
/// Points with a non-finite coordinate are left out.
pub fn pareto_front(points: &[(f64, f64)]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..points.len())
        .filter(|&i| points[i].0.is_finite() && points[i].1.is_finite())
        .collect();
    order.sort_by(|&a, &b| {
        let (pa, pb) = (points[a], points[b]);
        pa.0.total_cmp(&pb.0).then(pa.1.total_cmp(&pb.1))
    });
    let mut front = Vec::new();
    let mut best_error = f64::INFINITY;
    for i in order {
        if points[i].1 < best_error {
            best_error = points[i].1;
            front.push(i);
        }
    }
    front
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dominated_points_are_left_out() {
        let points = [
            (1.0, 5.0),
            (2.0, 3.0),
            (2.5, 4.0),
            (3.0, 1.0),
            (4.0, 1.0),
            (0.5, 9.0),
        ];
        assert_eq!(pareto_front(&points), vec![5, 0, 1, 3]);
    }

    #[test]
    fn every_point_off_the_front_is_dominated_by_one_on_it() {
        let points: Vec<(f64, f64)> = (0..50)
            .map(|i| {
                let x = (i * 37 % 50) as f64;
                (x, ((i * 11) % 17) as f64 + 100.0 / (x + 1.0))
            })
            .collect();
        let front = pareto_front(&points);
        for (i, p) in points.iter().enumerate() {
            if front.contains(&i) {
                continue;
            }
            assert!(
                front
                    .iter()
                    .any(|&f| points[f].0 <= p.0 && points[f].1 <= p.1),
                "{p:?} is not dominated"
            );
        }
        for pair in front.windows(2) {
            assert!(points[pair[0]].1 > points[pair[1]].1, "front errors fall");
        }
    }

    #[test]
    fn non_finite_points_are_ignored() {
        assert_eq!(
            pareto_front(&[(f64::NAN, 1.0), (1.0, f64::INFINITY), (2.0, 2.0)]),
            vec![2]
        );
    }
}
