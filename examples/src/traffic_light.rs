//! A traffic light (`plc/traffic_light.il`, through build.rs): 5 s red,
//! 1 s red + yellow, 4 s green, 2 s yellow; night mode flashes yellow.

use crate::plc::TrafficLight;
use crate::{SCAN, Timeline};
use il_std::Cycle;

/// Two full day cycles (24 s), then night mode for 4 s, then day again.
pub fn run() -> Timeline {
    let mut tl = Timeline::new(
        "traffic light: 5 s red, 1 s red+yellow, 4 s green, 2 s yellow; night mode flashes yellow",
        &["enable"],
        &["red", "yellow", "green", "phase"],
    );
    let mut ctx = Cycle::new();
    let mut light = TrafficLight {
        enable: true,
        ..TrafficLight::default()
    };
    while ctx.now().as_ms() <= 31_000 {
        let note = match ctx.now().as_ms() {
            0 => "power on, day mode",
            24_000 => {
                light.enable = false;
                "switch to night mode"
            }
            28_000 => {
                light.enable = true;
                "back to day mode"
            }
            _ => "",
        };
        light.call(&mut ctx);
        tl.record(
            ctx.now(),
            &[
                &light.enable,
                &light.red,
                &light.yellow,
                &light.green,
                &light.phase,
            ],
            note,
        );
        ctx.advance(SCAN);
    }
    tl
}
