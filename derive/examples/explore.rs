use thinjkr_derive::{ansatz, energy, nondimensional, sym::plain};
fn main() {
    let t = std::time::Instant::now();
    let e = energy::derive(&ansatz::ENERGY).expect("energy");
    println!("derived in {:?}", t.elapsed());
    println!("Pi = {}", plain(&e.potential));
    for r in &e.residuals { println!("r = {}", plain(r)); }
    println!("F = {}", plain(&e.fbar));
    println!("nd = {}", plain(&e.normal_derivative));
    for p in &e.pressure_parameters { println!("pp = {}", plain(p)); }
    match nondimensional::ratio_branch(&e.residuals) {
        Ok(b) => { println!("deg {}", b.degree); for c in &b.poly_t { println!("P: {}", plain(c)); } println!("X^d = {}", plain(&b.x_pow)); }
        Err(x) => println!("branch: {x}"),
    }
    match energy::axisymmetric(&e) { Ok((d, f)) => println!("axi dbar = {}, F = {}", plain(&d), plain(&f)), Err(x) => println!("axi: {x}") }
}
