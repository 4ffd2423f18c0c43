// The host loop of the new-user test (tests/tests/all/new_user.rs): the
// user's two crates `include!` it in their main.rs and the workspace test
// in its own module, each with `Tank` and `TankState` in scope, so all three
// run the same lines. The pump fills 50 raw units per 100 ms scan; draining
// empties 100 a scan.

/// 40 scans of the tank, one line each.
pub fn run() -> Vec<String> {
    let mut ctx = il_std::Cycle::new();
    let mut tank = Tank::default();
    let mut raw: i16 = 0;
    let mut lines = Vec::new();
    for scan in 0..40 {
        Tank::set_io_raw_level(&mut ctx, raw);
        ctx.io.set(il_std::addr::ix(0, 1), scan >= 30); // drain_req AT %IX0.1
        tank.call(&mut ctx);
        if Tank::io_pump(&ctx) {
            raw += 50;
        } else if tank.state == TankState::Draining {
            raw -= 100;
        }
        ctx.advance(il_std::TIME::from_ms(100));
        lines.push(format!(
            "scan {scan}: {:?} level {} pump {} lamp {} fills {}",
            tank.state,
            tank.reading.level,
            Tank::io_pump(&ctx),
            ctx.io.get(il_std::addr::qx(0, 2)),
            tank.fills.CV
        ));
    }
    lines
}
