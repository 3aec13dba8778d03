use nalgebra::DVector;
use std::time::Instant;
use thinjkr::conformal::{Conformal, Control};
fn main() {
    let m = Conformal::new(4).unwrap();
    let n = 2000;
    let t = Instant::now();
    let mut st = None;
    for _ in 0..n { st = Some(m.solve(0.8, Control::Force(1.0)).unwrap()); }
    println!("solve {:.2} us", t.elapsed().as_secs_f64() * 1e6 / n as f64);
    let st = st.unwrap();
    let mut x = DVector::from_vec(st.coefficients.clone()); x = x.push(st.delta_bar);
    let t = Instant::now();
    for _ in 0..n { std::hint::black_box(m.state(&x, 0.8).unwrap()); }
    println!("state {:.2} us", t.elapsed().as_secs_f64() * 1e6 / n as f64);
    let t = Instant::now();
    for _ in 0..n { std::hint::black_box(m.univalence(&st.coefficients).unwrap()); }
    println!("univalence {:.2} us", t.elapsed().as_secs_f64() * 1e6 / n as f64);
    let t = Instant::now();
    for _ in 0..n { std::hint::black_box(m.bc_defect(&x, 0.8)); }
    println!("bc_defect {:.2} us", t.elapsed().as_secs_f64() * 1e6 / n as f64);
    let t = Instant::now();
    for _ in 0..n { std::hint::black_box(m.potential(&x, 0.8)); }
    println!("potential(2) {:.2} us", t.elapsed().as_secs_f64() * 1e6 / n as f64);
    let t = Instant::now();
    for _ in 0..n { std::hint::black_box(m.solve(1.0, Control::Force(1.0)).unwrap()); }
    println!("solve rho=1 {:.2} us", t.elapsed().as_secs_f64() * 1e6 / n as f64);
    println!("{:?}", st.coefficients);
}
