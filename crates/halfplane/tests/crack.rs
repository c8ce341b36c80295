//! The crack module against independent references (`docs/crack.md`).

use halfplane::crack::{Crack, CrackSolver};
use halfplane::Material;
use std::f64::consts::PI;

fn steel() -> Material {
    Material::new(200_000.0, 0.3).unwrap()
}

/// `K_I/(sigma sqrt(pi l))` of a crack normal to the surface under a face load `p(s/l)`.
fn normal_factor(points: usize, load: impl Fn(f64) -> f64) -> (f64, f64) {
    let l = 0.01;
    let crack = Crack::new(0.0, 0.0, l).unwrap();
    let solver = CrackSolver::new(&crack, &steel(), points).unwrap();
    let normal: Vec<f64> = solver.distances().iter().map(|s| load(s / l)).collect();
    let shear = vec![0.0; normal.len()];
    let k = solver.open(&normal, &shear).unwrap();
    let f = (PI * l).sqrt();
    (k.k1 / f, k.k2 / f)
}

#[test]
fn edge_crack_under_uniform_tension() {
    for n in [10, 20, 40, 80, 160] {
        let (f1, f2) = normal_factor(n, |_| 1.0);
        println!("{n} {f1:.7} {f2:.2e}");
    }
}
