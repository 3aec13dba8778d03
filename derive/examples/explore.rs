use thinjkr_derive::{ansatz, model::Derivation, sym::plain};
fn main() {
    let d = Derivation::new(&ansatz::APEX_45).expect("apex45");
    for (n, v) in &d.collocation { println!("{n} = {}", plain(v)); }
    println!("u_max = {}", plain(&d.extrema.u_max));
    println!("apex = {}", plain(&d.extrema.apex));
    println!("eta = {}", plain(&d.eta));
    println!("res0 = {}", plain(&d.residuals[0]));
}
