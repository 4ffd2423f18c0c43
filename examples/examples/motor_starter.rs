//! `cargo run -p il-examples --example motor_starter`: a motor starter with interlocks (SR, RS, R_TRIG) wired through the process image,
//! driven over simulated time; prints the time-line of inputs and outputs.

fn main() {
    print!("{}", il_examples::motor_starter::run());
}
