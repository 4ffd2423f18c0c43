//! `cargo run -p il-examples --example batch_weigh`: batch weighing with a WEIGH-like FUNCTION (EN/ENO, BCD) and a recorded fault,
//! driven over simulated time; prints the time-line of inputs and outputs.

fn main() {
    print!("{}", il_examples::batch_weigh::run());
}
