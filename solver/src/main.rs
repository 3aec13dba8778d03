//! `thinjkr`: the approximate JKR model of coated cylinders from the command
//! line (`thinjkr::cli`). With no arguments it prints the paper's ρ = 0.8
//! example.

fn main() -> std::process::ExitCode {
    thinjkr::cli::main()
}
