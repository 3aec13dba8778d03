//! `thinjkr batch` and the batch API: a 10⁴-line CSV round-trips (every
//! output row is the state `solve` gives for its input, in input order),
//! and a malformed line gives an error row naming the line while the rest
//! is still written.

use std::io::Write;
use std::process::{Command, Stdio};
use thinjkr::batch::{solve_all, solve_one, Given, Item};
use thinjkr::ModelId;

fn run(input: &str) -> (String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_thinjkr"))
        .args(["batch", "--model", "max"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("runs");
    // the input is written from another thread: the output is read while
    // it streams (a full pipe would otherwise block both)
    let mut stdin = child.stdin.take().unwrap();
    let input = input.to_string();
    let writer = std::thread::spawn(move || stdin.write_all(input.as_bytes()).unwrap());
    let out = child.wait_with_output().unwrap();
    writer.join().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    (
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn ten_thousand_lines_round_trip_in_order() {
    let items: Vec<Item> = (0u64..10_000)
        .map(|k| {
            let rho = 0.3 + 0.7 * ((k * 7919) % 10_000) as f64 / 10_000.0;
            let given = if k % 2 == 0 {
                Given::Delta(-0.5 + 10.0 * ((k * 104_729) % 10_000) as f64 / 10_000.0)
            } else {
                Given::Force(-1.0 + 20.0 * ((k * 1_299_709) % 10_000) as f64 / 10_000.0)
            };
            Item { rho, given }
        })
        .collect();
    let mut input = String::from("rho,control,value\n");
    for it in &items {
        match it.given {
            Given::Delta(v) => input.push_str(&format!("{:?},delta,{v:?}\n", it.rho)),
            Given::Force(v) => input.push_str(&format!("{:?},force,{v:?}\n", it.rho)),
        }
    }
    let (out, _) = run(&input);
    let rows: Vec<&str> = out.lines().skip(1).collect();
    assert_eq!(rows.len(), items.len());
    let direct = solve_all(ModelId::Max, &items);
    let mut states = 0;
    for (k, (row, (it, res))) in rows.iter().zip(items.iter().zip(&direct)).enumerate() {
        let f: Vec<&str> = row.splitn(13, ',').collect();
        assert_eq!(
            f[0].parse::<usize>().unwrap(),
            k + 2,
            "line numbers in order"
        );
        assert_eq!(f[1].parse::<f64>().unwrap(), it.rho);
        match res {
            Ok(st) => {
                states += 1;
                assert_eq!(f[4].parse::<f64>().unwrap(), st.a, "row {row}");
                assert_eq!(f[8].parse::<f64>().unwrap(), st.force, "row {row}");
                assert_eq!(f[12], "");
            }
            Err(e) => assert!(f[12].contains(&e.to_string().replace('"', "'")), "{row}"),
        }
        // and the parallel batch equals the one-by-one solve (every 10th)
        if k % 10 == 0 {
            assert_eq!(res, &solve_one(ModelId::Max, it));
        }
    }
    assert!(states > 9000, "{states} states");
}

#[test]
fn a_malformed_line_is_reported_and_the_rest_written() {
    let (out, err) =
        run("rho,control,value\n0.8,delta,2\n0.8,delta\n0.8,size,1\nx,force,1\n0.5,force,-1\n");
    let rows: Vec<&str> = out.lines().collect();
    assert_eq!(rows.len(), 6, "{out}");
    assert!(rows[1].starts_with("2,0.8,delta,2.0,3.2117"), "{}", rows[1]);
    for (row, line) in [(2, 3), (3, 4), (4, 5)] {
        assert!(rows[row].starts_with(&format!("{line},,")), "{}", rows[row]);
        assert!(rows[row].contains(&format!("line {line}")), "{}", rows[row]);
        assert!(err.contains(&format!("line {line}")), "{err}");
    }
    assert!(rows[5].starts_with("6,0.5,force,-1.0,2.87"), "{}", rows[5]);
}
