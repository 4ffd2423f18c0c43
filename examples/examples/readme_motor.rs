//! `cargo run -p il-examples --example readme_motor`: the README's motor.il through il!(file = ...),
//! driven over simulated time; prints the time-line of inputs and outputs.

fn main() {
    print!("{}", il_examples::readme_motor::run());
}
