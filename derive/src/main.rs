use thinjkr_derive::{ansatz, model::Derivation, sym::plain};
fn main() {
    let t = std::time::Instant::now();
    for a in ansatz::ALL {
        let d = match Derivation::new(a) {
            Ok(d) => d,
            Err(e) => {
                println!("{}: ERROR {e}", a.id);
                continue;
            }
        };
        println!("== {} ({:?})", a.id, t.elapsed());
        for l in &d.laplace {
            println!("(6) {:?}: {}", l.monomial, plain(&l.residual));
        }
        println!("(8) {}", plain(&d.force));
        println!("(9) {}", plain(&d.normal_derivative.value()));
        for (n, v) in &d.collocation {
            println!("(10) {n} = {}", plain(v));
        }
        println!("(11) {}", plain(&d.normal_derivative_collocated.value()));
        println!(
            "crit {:?}",
            d.extrema
                .critical_points
                .iter()
                .map(plain)
                .collect::<Vec<_>>()
        );
        println!(
            "umax {} umin {}",
            plain(&d.extrema.u_max),
            plain(&d.extrema.u_min)
        );
        println!("eta {}", plain(&d.eta));
        println!("(14) {}", plain(&d.bc_error));
        println!("(13) xi = {}", plain(&d.xi_adhesion));
        println!("p0 = {}", plain(&d.p0_explicit));
        for x in &d.xi {
            println!("(15) {}", plain(x));
        }
        for r in &d.residuals {
            println!("(19/20) {}", plain(r));
        }
        println!("(18) {}", plain(&d.fbar_reduced));
        if let Some(b) = &d.branch {
            println!(
                "branch X {}\n  Y {}",
                plain(&b.abar_cubed),
                plain(&b.dbar_abar)
            );
        }
        let l = match &d.limits {
            Ok(l) => l,
            Err(e) => {
                println!("limits: {e}");
                continue;
            }
        };
        println!(
            "axi eta1 {} dbar {} fbar {} crit {} {} {}",
            plain(&l.axisymmetric.eta_at_1),
            plain(&l.axisymmetric.dbar),
            plain(&l.axisymmetric.fbar),
            plain(&l.axisymmetric.critical.0),
            plain(&l.axisymmetric.critical.1),
            plain(&l.axisymmetric.critical.2)
        );
        println!(
            "(22) {}  (23) {}",
            plain(&l.axisymmetric.delta),
            plain(&l.axisymmetric.force)
        );
        println!(
            "zf dbar {} a3 {} rho {}",
            plain(&l.zero_force.dbar),
            plain(&l.zero_force.abar_cubed),
            plain(&l.zero_force.rho)
        );
        println!("nonadh rho {}", plain(&l.non_adhesive_rho));
        println!(
            "nc exact delta {} a2 {}",
            plain(&l.near_circular_exact.delta),
            plain(&l.near_circular_exact.a2)
        );
        println!(
            "nc model s1 {} etap {} xi0 {}",
            plain(&l.near_circular_model.s1),
            plain(&l.near_circular_model.eta_prime_1),
            plain(&l.near_circular_model.xi0)
        );
    }
    println!("total {:?}", t.elapsed());
}
