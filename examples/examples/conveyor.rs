//! `cargo run -p il-examples --example conveyor`: a conveyor counter (CTU, CTD, TP),
//! driven over simulated time; prints the time-line of inputs and outputs.

fn main() {
    print!("{}", il_examples::conveyor::run());
}
