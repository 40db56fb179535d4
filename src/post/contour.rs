//! Iso-lines of a scalar field on a tensor-product grid (marching squares), joined into polylines.

/// A polyline as a list of (x, y) points. A closed loop repeats its first point at the end.
pub type Polyline = Vec<[f64; 2]>;

const NONE: u32 = u32::MAX;

/// Iso-lines of `values` (given at the grid points `xs × ys`, x fastest) for each level in
/// `levels`. Returns `(level index, polyline)` pairs.
///
/// Cells with a NaN corner are skipped. Saddle cells are resolved with the cell-centre average.
/// Each polyline is a maximal chain of crossing points; lines ending at the grid boundary (or at
/// a skipped cell) are open, the others are closed loops.
pub fn isolines(values: &[f64], xs: &[f64], ys: &[f64], levels: &[f64]) -> Vec<(usize, Polyline)> {
    let (nx, ny) = (xs.len(), ys.len());
    assert_eq!(
        values.len(),
        nx * ny,
        "isolines: values do not match the grid"
    );
    let mut out = Vec::new();
    if nx < 2 || ny < 2 {
        return out;
    }
    let n_h = (nx - 1) * ny; // horizontal edges (i,j)-(i+1,j)
    let n_edges = n_h + nx * (ny - 1); // + vertical edges (i,j)-(i,j+1)
    let h_id = |i: usize, j: usize| (i + (nx - 1) * j) as u32;
    let v_id = |i: usize, j: usize| (n_h + i + nx * j) as u32;
    let val = |i: usize, j: usize| values[i + nx * j];

    // Edge -> up to two neighbouring edges (the segments through it), reused across levels.
    let mut nbr: Vec<[u32; 2]> = vec![[NONE, NONE]; n_edges];
    let mut visited: Vec<bool> = vec![false; n_edges];
    let mut touched: Vec<u32> = Vec::new();

    for (li, &level) in levels.iter().enumerate() {
        if !level.is_finite() {
            continue;
        }
        touched.clear();
        let mut link = |a: u32, b: u32, touched: &mut Vec<u32>| {
            for (e, other) in [(a, b), (b, a)] {
                let slot = &mut nbr[e as usize];
                if slot[0] == NONE {
                    slot[0] = other;
                    touched.push(e);
                } else if slot[1] == NONE {
                    slot[1] = other;
                }
            }
        };
        for j in 0..ny - 1 {
            for i in 0..nx - 1 {
                let c = [val(i, j), val(i + 1, j), val(i + 1, j + 1), val(i, j + 1)];
                if c.iter().any(|v| v.is_nan()) {
                    continue;
                }
                let above = c.map(|v| v >= level);
                let case = above
                    .iter()
                    .enumerate()
                    .fold(0u8, |acc, (k, &a)| acc | ((a as u8) << k));
                if case == 0 || case == 15 {
                    continue;
                }
                // Edges: 0 bottom, 1 right, 2 top, 3 left; edge k joins corners k and k+1.
                let edges = [h_id(i, j), v_id(i + 1, j), h_id(i, j + 1), v_id(i, j)];
                let crossing: Vec<usize> =
                    (0..4).filter(|&k| above[k] != above[(k + 1) % 4]).collect();
                if crossing.len() == 2 {
                    link(edges[crossing[0]], edges[crossing[1]], &mut touched);
                } else {
                    // Saddle: corners 0 and 2 on one side, 1 and 3 on the other.
                    let centre_above = 0.25 * (c[0] + c[1] + c[2] + c[3]) >= level;
                    // Cut off the two corners that are on the other side from the centre.
                    if centre_above == above[0] {
                        // centre joins corners 0 and 2: cut off corners 1 and 3.
                        link(edges[0], edges[1], &mut touched);
                        link(edges[2], edges[3], &mut touched);
                    } else {
                        // cut off corners 0 and 2.
                        link(edges[3], edges[0], &mut touched);
                        link(edges[1], edges[2], &mut touched);
                    }
                }
            }
        }

        let point = |e: u32| -> [f64; 2] {
            let e = e as usize;
            if e < n_h {
                let (i, j) = (e % (nx - 1), e / (nx - 1));
                let (a, b) = (val(i, j), val(i + 1, j));
                let t = ((level - a) / (b - a)).clamp(0.0, 1.0);
                [xs[i] + t * (xs[i + 1] - xs[i]), ys[j]]
            } else {
                let e = e - n_h;
                let (i, j) = (e % nx, e / nx);
                let (a, b) = (val(i, j), val(i, j + 1));
                let t = ((level - a) / (b - a)).clamp(0.0, 1.0);
                [xs[i], ys[j] + t * (ys[j + 1] - ys[j])]
            }
        };

        let walk = |start: u32, visited: &mut Vec<bool>| -> Polyline {
            let mut line = vec![point(start)];
            visited[start as usize] = true;
            let mut prev = NONE;
            let mut cur = start;
            loop {
                let [a, b] = nbr[cur as usize];
                let next = if a != NONE && a != prev && !visited[a as usize] {
                    a
                } else if b != NONE && b != prev && !visited[b as usize] {
                    b
                } else {
                    // Closed loop: back at the start?
                    if (a == start || b == start) && prev != NONE && line.len() > 2 {
                        line.push(line[0]);
                    }
                    break;
                };
                visited[next as usize] = true;
                line.push(point(next));
                prev = cur;
                cur = next;
            }
            line
        };

        // Open lines first (start at an end: one neighbour), then the closed loops.
        for &e in &touched {
            let [_, b] = nbr[e as usize];
            if b == NONE && !visited[e as usize] {
                let line = walk(e, &mut visited);
                if line.len() >= 2 {
                    out.push((li, line));
                }
            }
        }
        for &e in &touched {
            if !visited[e as usize] {
                let line = walk(e, &mut visited);
                if line.len() >= 2 {
                    out.push((li, line));
                }
            }
        }
        for &e in &touched {
            nbr[e as usize] = [NONE, NONE];
            visited[e as usize] = false;
        }
        // Edges linked only as the second neighbour of someone are in `touched` too (each link
        // touches both ends), so the reset above is complete.
    }
    out
}

/// Ramer–Douglas–Peucker simplification: drops points closer than `tolerance` to the chord of
/// their neighbours. Keeps the end points (so closed loops stay closed).
pub fn simplify_polyline(line: &[[f64; 2]], tolerance: f64) -> Polyline {
    let n = line.len();
    if n <= 2 || tolerance <= 0.0 {
        return line.to_vec();
    }
    let mut keep = vec![false; n];
    keep[0] = true;
    keep[n - 1] = true;
    let mut stack = vec![(0usize, n - 1)];
    let tol2 = tolerance * tolerance;
    while let Some((a, b)) = stack.pop() {
        if b <= a + 1 {
            continue;
        }
        let (pa, pb) = (line[a], line[b]);
        let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
        let len2 = dx * dx + dy * dy;
        let mut worst = (0.0, a);
        for (k, p) in line.iter().enumerate().take(b).skip(a + 1) {
            let (qx, qy) = (p[0] - pa[0], p[1] - pa[1]);
            let d2 = if len2 > 0.0 {
                let cross = qx * dy - qy * dx;
                cross * cross / len2
            } else {
                qx * qx + qy * qy
            };
            if d2 > worst.0 {
                worst = (d2, k);
            }
        }
        if worst.0 > tol2 {
            keep[worst.1] = true;
            stack.push((a, worst.1));
            stack.push((worst.1, b));
        }
    }
    line.iter()
        .zip(keep)
        .filter_map(|(p, k)| k.then_some(*p))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(n: usize, lo: f64, hi: f64) -> Vec<f64> {
        (0..n)
            .map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64)
            .collect()
    }

    #[test]
    fn straight_line_of_a_linear_field() {
        let xs = grid(11, 0.0, 1.0);
        let ys = grid(7, 0.0, 2.0);
        let vals: Vec<f64> = ys
            .iter()
            .flat_map(|&y| xs.iter().map(move |&x| x + 0.0 * y))
            .collect();
        let lines = isolines(&vals, &xs, &ys, &[0.55]);
        assert_eq!(lines.len(), 1);
        let line = &lines[0].1;
        assert_eq!(line.len(), 7);
        for p in line {
            assert!((p[0] - 0.55).abs() < 1e-12);
        }
    }

    #[test]
    fn circle_is_one_closed_loop() {
        let xs = grid(41, -1.0, 1.0);
        let ys = grid(41, -1.0, 1.0);
        let vals: Vec<f64> = ys
            .iter()
            .flat_map(|&y| xs.iter().map(move |&x| x * x + y * y))
            .collect();
        let lines = isolines(&vals, &xs, &ys, &[0.25, 0.64]);
        assert_eq!(lines.len(), 2);
        for (li, line) in &lines {
            let r = [0.5, 0.8][*li];
            assert_eq!(line.first(), line.last(), "closed");
            for p in line {
                let rr = (p[0] * p[0] + p[1] * p[1]).sqrt();
                assert!((rr - r).abs() < 0.01, "r {rr} vs {r}");
            }
        }
    }

    #[test]
    fn simplify_keeps_corners() {
        let line: Polyline = (0..=10)
            .map(|i| [i as f64, 0.0])
            .chain((1..=10).map(|i| [10.0, i as f64]))
            .collect();
        let s = simplify_polyline(&line, 1e-6);
        assert_eq!(s, vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0]]);
    }
}
