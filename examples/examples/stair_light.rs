//! `cargo run -p il-examples --example stair_light`: a staircase light (TOF) written inline with il!,
//! driven over simulated time; prints the time-line of inputs and outputs.

fn main() {
    print!("{}", il_examples::stair_light::run());
}
