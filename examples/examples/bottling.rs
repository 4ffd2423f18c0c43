//! `cargo run -p il-examples --example bottling`: a CONFIGURATION of two
//! tasks at different intervals (`examples/plc/bottling.il`), driven over
//! simulated time; prints which program ran when.

fn main() {
    print!("{}", il_examples::bottling::run());
}
