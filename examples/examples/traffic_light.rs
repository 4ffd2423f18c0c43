//! `cargo run -p il-examples --example traffic_light`: a TON sequence in IL
//! (`examples/plc/traffic_light.il`), compiled by build.rs, driven over
//! simulated time.

fn main() {
    print!("{}", il_examples::traffic_light::run());
}
