//! The committed figures in docs/figures/ equal what `thinjkr figures`
//! draws now (deterministic output). On a mismatch the fresh file is written
//! and the test fails: review and commit (or run
//! `cargo run --release -p thinjkr -- figures --out docs/figures`).

#[test]
fn figures_are_fresh_and_deterministic() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/figures");
    let a = thinjkr::figures::all().expect("figures draw");
    let b = thinjkr::figures::all().expect("figures draw twice");
    assert!(a.len() >= 9, "{} figures", a.len());
    assert_eq!(a, b, "figure output is not deterministic");
    let mut stale = Vec::new();
    for (name, svg) in &a {
        let p = dir.join(name);
        if std::fs::read_to_string(&p).ok().as_deref() != Some(svg.as_str()) {
            std::fs::create_dir_all(&dir).unwrap();
            std::fs::write(&p, svg).unwrap();
            stale.push(*name);
        }
    }
    assert!(
        stale.is_empty(),
        "stale figures rewritten, commit them: {stale:?}"
    );
}

/// The exact solution's figures (docs/figures/exact_*.svg) are what
/// `thinjkr accuracy --figures docs/figures` draws from the committed
/// reference derive/data/exact_reference.json (whose freshness
/// solver/tests/accuracy_table.rs checks), and the band map
/// (exact_bands.svg) and F̄(ā) over the bands (exact_bands_force_*.svg)
/// what `figures::exact_bands` and `figures::exact_bands_force` draw from
/// the committed band maps docs/data/exact_bands.jsonl (and the reach map
/// docs/data/exact_reach.jsonl).
#[test]
fn exact_figures_are_fresh() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let text = std::fs::read_to_string(root.join("derive/data/exact_reference.json"))
        .expect("the exact reference exists");
    let reference: thinjkr::accuracy::Reference =
        serde_json::from_str(&text).expect("the exact reference parses");
    let mut figs = thinjkr::figures::exact_all(&reference).expect("exact figures draw");
    assert_eq!(figs.len(), 5);
    // the band map, from the committed band maps (whose ρ = 0.8 line
    // solver/tests/bands.rs recomputes)
    let bands = thinjkr::report::band_maps_from_json_lines(
        &std::fs::read_to_string(root.join("docs/data/exact_bands.jsonl"))
            .expect("the committed band maps exist"),
    )
    .expect("band map lines");
    // with the reach of each size, the same map by a second route at every
    // ρ (docs/data/exact_reach.jsonl, whose ā = 3.8 the lib's
    // studies::reach tests recompute)
    let reach = std::fs::read_to_string(root.join("docs/data/exact_reach.jsonl"))
        .expect("the committed reach map exists");
    figs.push(
        thinjkr::figures::exact_bands(&bands, &reach, &reference).expect("the band map draws"),
    );
    // and F̄(ā) over the bands, one figure per ρ
    let force = thinjkr::figures::exact_bands_force(&bands).expect("the F(a) figures draw");
    // one per ρ of the six that `figures::BANDS_FORCE_FILES` names (each
    // committed figure is then held below)
    assert_eq!(force.len(), 6);
    figs.extend(force);
    let mut stale = Vec::new();
    for (name, svg) in &figs {
        let p = root.join("docs/figures").join(name);
        if std::fs::read_to_string(&p).ok().as_deref() != Some(svg.as_str()) {
            std::fs::write(&p, svg).unwrap();
            stale.push(*name);
        }
    }
    assert!(
        stale.is_empty(),
        "stale exact figures rewritten, commit them: {stale:?}"
    );
}
