//! A packing conveyor (`plc/conveyor.il`, through build.rs): CTU counts
//! boxes into a carton, TP pushes full cartons off, CTD counts the cartons
//! left in the order.

use crate::plc::Conveyor;
use crate::{SCAN, Timeline};
use il_std::Cycle;

/// Boxes on the belt pass the photo eye every 0.6 s of belt movement and
/// cover it for 0.2 s. An order of 3 cartons of 4 boxes.
pub fn run() -> Timeline {
    let mut tl = Timeline::new(
        "conveyor: 4 boxes per carton (CTU), 0.5 s pusher stroke (TP), order of 3 cartons (CTD)",
        &["start", "order", "eye"],
        &["motor", "boxes", "pusher", "left", "done"],
    );
    let mut ctx = Cycle::new();
    let mut c = Conveyor::default();
    let mut belt_ms = 0i64; // how far the belt has moved, in ms of running
    while ctx.now().as_ms() <= 10_000 {
        let note = match ctx.now().as_ms() {
            0 => "power on: no order",
            300 => {
                c.new_order = true;
                "load an order of 3 cartons"
            }
            400 => {
                c.new_order = false;
                ""
            }
            600 => {
                c.start = true;
                "start the belt"
            }
            _ => "",
        };
        c.box_eye = (300..500).contains(&(belt_ms % 600));
        c.call(&mut ctx);
        if c.motor {
            belt_ms += SCAN.as_ms();
        }
        tl.record(
            ctx.now(),
            &[
                &c.start,
                &c.new_order,
                &c.box_eye,
                &c.motor,
                &c.in_carton,
                &c.pusher,
                &c.cartons_left,
                &c.order_done,
            ],
            note,
        );
        ctx.advance(SCAN);
    }
    tl
}
