//! RETAIN snapshots (`plc/retain.il`): a host saves them and restores them
//! into a fresh instance (a warm start); everything else starts over.

use il_std::Cycle;

macro_rules! retain_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{Fleet, Odometer, Vehicle};

            fn run(v: &mut Vehicle, scans: usize) {
                let mut ctx = Cycle::new();
                for _ in 0..scans {
                    v.call(&mut ctx);
                }
            }

            #[test]
            fn block_snapshot_holds_only_retain_variables() {
                let mut o = Odometer::default();
                o.add = 7;
                o.call(&mut Cycle::new());
                let s = o.retain();
                assert_eq!(s.km, 7);
                let mut fresh = Odometer::default();
                fresh.restore(&s);
                assert_eq!((fresh.km, fresh.trips), (7, 0));
            }

            #[test]
            fn program_snapshot_nests_instances_and_arrays() {
                let mut v = Vehicle::default();
                run(&mut v, 4);
                let s = v.retain();
                assert_eq!(s.hours, 4);
                assert_eq!(s.odo.km, 20);
                assert_eq!([s.wheels[0].km, s.wheels[1].km], [0, 4]);
                assert_eq!(s.starts.CV, 2); // a RETAIN standard block is kept whole
                let mut warm = Vehicle::default();
                warm.restore(&s);
                assert_eq!((warm.hours, warm.odo.km, warm.wheels[1].km), (4, 20, 4));
                assert_eq!(warm.starts.CV, 2);
                // Not RETAIN: back to the initial values.
                assert_eq!(
                    (warm.speed, warm.odo.trips, warm.wheels[1].trips),
                    (0, 0, 0)
                );
                run(&mut warm, 1);
                assert_eq!((warm.hours, warm.odo.km), (5, 25));
            }

            #[test]
            fn configuration_snapshot_holds_globals_and_programs() {
                let mut f = Fleet::default();
                let mut ctx = Cycle::new();
                f.run(&mut ctx);
                f.run(&mut ctx);
                f.total = 99;
                f.scratch = 5;
                let s = f.retain();
                let mut warm = Fleet::default();
                warm.restore(&s);
                assert_eq!((warm.total, warm.scratch), (99, 0));
                assert_eq!((warm.Truck.hours, warm.Truck.speed), (2, 0));
                assert_eq!(s.Truck.hours, 2);
            }
        }
    };
}

retain_tests!(via_build);
retain_tests!(via_macro);

/// build.rs compiles with `Builder::serde(true)`: a snapshot goes through
/// JSON and back (arrays longer than 32, 2-D arrays, strings, TIME, a
/// standard block kept whole, nested FB snapshots).
#[test]
fn snapshots_round_trip_through_serde() {
    use il_tests::via_build::{Fleet, Vehicle, Vehicle__Retain};
    let mut v = Vehicle::default();
    let mut ctx = Cycle::new();
    for _ in 0..3 {
        v.call(&mut ctx);
    }
    let s = v.retain();
    assert_eq!(
        (s.log[39], s.grid[1][2], s.uptime),
        (3, true, il_std::TIME::from_ms(3000))
    );
    assert_eq!(s.driver.to_string(), "Ada");
    let json = serde_json::to_string(&s).unwrap();
    let back: Vehicle__Retain = serde_json::from_str(&json).unwrap();
    assert_eq!(back, s);
    let mut warm = Vehicle::default();
    warm.restore(&back);
    assert_eq!((warm.hours, warm.log[39], warm.odo.km), (3, 3, 15));
    // A whole configuration snapshot, too.
    let mut f = Fleet::default();
    f.run(&mut ctx);
    f.total = 7;
    let json = serde_json::to_string(&f.retain()).unwrap();
    assert!(json.contains("\"total\":7"), "{json}");
    // A wrong length is an error, not a panic.
    let bad = json.replace("\"total\":7", "\"total\":\"x\"");
    assert!(serde_json::from_str::<il_tests::via_build::Fleet__Retain>(&bad).is_err());
}
