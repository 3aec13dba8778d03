//! thinjkr-derive: the symbolic derivation of the approximate JKR model of
//! Argatov, Mishuris & Popov (2016, Tribology Letters 64:12), a checker that
//! holds every printed claim of the paper against it, and the generator of
//! the solver's Rust code and of the reports in `docs/`.
//!
//! The derivation is generic over an [`ansatz::Ansatz`]: the paper's (5)
//! with collocation (10) and closure (13) is one value of it; the closure
//! of (3)₂ is part of the data ([`ansatz::Closure`]).
//!
//! symbolica runs here in its unlicensed restricted mode, which allows one
//! symbolica thread per user at a time: call this crate from one thread only.

pub mod accuracy;
pub mod ansatz;
pub mod check;
pub mod claims;
pub mod codegen;
pub mod codegen_conformal;
pub mod conformal;
pub mod contour;
pub mod energy;
pub mod force;
pub mod generate;
pub mod ir;
pub mod limits;
pub mod model;
pub mod nondimensional;
pub mod numeric;
pub mod report;
pub mod routes;
pub mod special;
pub mod sym;
pub mod thin_layer;
