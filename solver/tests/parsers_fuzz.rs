//! Arbitrary bytes into the batch line parser and the TOML contact file
//! reader (proptest, a fixed number of cases per run): neither panics;
//! every batch line but a header on line 1 becomes an item or an error
//! that names its line, and an error quotes at most 40 characters of it.

use proptest::prelude::*;
use thinjkr::batch::{decode_line, parse_line};
use thinjkr::units::Cylinders;

proptest! {
    #![proptest_config(ProptestConfig { cases: 4000, ..ProptestConfig::default() })]

    #[test]
    fn batch_lines_never_panic_and_always_get_a_row(
        raw in proptest::collection::vec(any::<u8>(), 0..200),
        number in 1usize..5,
    ) {
        let parsed = match decode_line(number, &raw) {
            Ok(line) => parse_line(number, line),
            Err(e) => Some(Err(e)),
        };
        match parsed {
            None => prop_assert_eq!(number, 1, "only line 1 may be skipped"),
            Some(Ok(_)) => {}
            Some(Err(e)) => {
                let msg = e.to_string();
                let line_number = format!("line {number}");
                prop_assert!(msg.contains(&line_number), "{}", msg);
                prop_assert!(msg.chars().count() < 400, "{}", msg);
            }
        }
    }

    #[test]
    fn batch_lines_near_the_format_never_panic(
        rho in "[-+0-9.eEnaNif]{0,12}",
        control in "(delta|force|size|)",
        value in "[-+0-9.eEnaNif]{0,12}",
        extra in proptest::option::of("[ ,#a-z]{0,5}"),
    ) {
        let line = format!("{rho},{control},{value}{}", extra.unwrap_or_default());
        let parsed = parse_line(2, &line);
        prop_assert!(parsed.is_some());
    }

    #[test]
    fn contact_files_never_panic(text in "[a-z_0-9=.\\-\\n \"\\[\\]#e]{0,200}") {
        let _ = toml::from_str::<Cylinders>(&text);
    }

    #[test]
    fn contact_files_with_every_key_and_arbitrary_values(
        values in proptest::collection::vec(any::<f64>(), 8),
    ) {
        let keys = ["r1", "r2", "theta_deg", "h1", "h2", "g1", "g2", "work_of_adhesion"];
        let text: String = keys
            .iter()
            .zip(&values)
            .map(|(k, v)| format!("{k} = {}\n", if v.is_finite() { format!("{v:e}") } else if v.is_nan() { "nan".into() } else if *v > 0.0 { "inf".into() } else { "-inf".into() }))
            .collect();
        if let Ok(c) = toml::from_str::<Cylinders>(&text) {
            // a file that reads is solved or refused with a typed error, never a non-finite number
            if let Ok(st) = c.at_load(0.0) {
                prop_assert!(st.a.is_finite() && st.force.is_finite());
            }
        }
    }
}
