//! Every example's time-line: the key transitions, and the whole printed
//! text against `tests/expected/NAME.txt` (refresh with `IL_BLESS=1`).

use il_examples::{
    ALL, Timeline, batch_weigh, bottling, conveyor, motor_starter, stair_light, traffic_light,
};
use il_std::TIME;
use std::path::Path;

fn ms(t: i64) -> TIME {
    TIME::from_ms(t)
}

/// Each `examples/NAME.rs` has an entry in `ALL` and the other way round,
/// and every example's output matches its expected text. This is the test
/// that "runs every example binary": the binaries only print `run()`.
#[test]
fn every_example_runs_and_matches_its_expected_output() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut bins: Vec<String> = std::fs::read_dir(dir.join("examples"))
        .unwrap()
        .filter_map(|e| {
            let p = e.unwrap().path();
            (p.extension()? == "rs").then(|| p.file_stem().unwrap().to_string_lossy().into())
        })
        .collect();
    bins.sort();
    let mut names: Vec<String> = ALL.iter().map(|(n, _)| n.to_string()).collect();
    names.sort();
    assert_eq!(bins, names, "examples/*.rs and il_examples::ALL differ");

    let bless = std::env::var_os("IL_BLESS").is_some();
    let mut stale = Vec::new();
    for (name, run) in ALL {
        let text = run().to_string();
        // The binary does exactly this.
        let src = std::fs::read_to_string(dir.join(format!("examples/{name}.rs"))).unwrap();
        assert!(
            src.contains(&format!("il_examples::{name}::run()")),
            "examples/{name}.rs does not print {name}::run()"
        );
        let path = dir.join(format!("tests/expected/{name}.txt"));
        if bless {
            std::fs::write(&path, &text).unwrap();
        } else if std::fs::read_to_string(&path).ok().as_deref() != Some(text.as_str()) {
            stale.push(format!(
                "--- {name}: expected {}, got:\n{text}",
                path.display()
            ));
        }
    }
    assert!(
        stale.is_empty(),
        "{}\nrun with IL_BLESS=1 to accept",
        stale.join("\n")
    );
}

fn lamps(tl: &Timeline, t: i64) -> (&str, &str, &str) {
    (
        tl.at(ms(t), "red"),
        tl.at(ms(t), "yellow"),
        tl.at(ms(t), "green"),
    )
}

#[test]
fn traffic_light_phases_at_the_right_times() {
    let tl = traffic_light::run();
    // phase: 0 red (5 s), 1 red+yellow (1 s), 2 green (4 s), 3 yellow (2 s).
    let changes: Vec<(i64, &str)> = tl
        .changes("phase")
        .into_iter()
        .map(|(t, v)| (t.as_ms(), v))
        .collect();
    assert_eq!(
        changes[..9],
        [
            (0, "0"),
            (5_000, "1"),
            (6_000, "2"),
            (10_000, "3"),
            (12_000, "0"),
            (17_000, "1"),
            (18_000, "2"),
            (22_000, "3"),
            (24_000, "0"),
        ]
    );
    assert_eq!(lamps(&tl, 4_900), ("1", "0", "0"));
    assert_eq!(lamps(&tl, 5_000), ("1", "1", "0"));
    assert_eq!(lamps(&tl, 6_000), ("0", "0", "1"));
    assert_eq!(lamps(&tl, 9_900), ("0", "0", "1"));
    assert_eq!(lamps(&tl, 10_000), ("0", "1", "0"));
    assert_eq!(lamps(&tl, 12_000), ("1", "0", "0"));
    // Night mode from 24 s: only yellow, one second off, one second on.
    assert_eq!(
        tl.times_of("yellow", "1"),
        [5_000, 10_000, 17_000, 22_000, 25_000, 27_000]
    );
    assert_eq!(tl.times_of("green", "1"), [6_000, 18_000]);
    // Day mode again at 28 s starts with red.
    assert_eq!(lamps(&tl, 28_000), ("1", "0", "0"));
}

#[test]
fn motor_starter_interlocks() {
    let tl = motor_starter::run();
    assert_eq!(tl.times_of("contactor", "1"), [500, 3_400, 7_000]);
    assert_eq!(tl.times_of("contactor", "0"), [0, 1_500, 4_000]);
    // Held START while the guard closes at 2.6 s: no start (R_TRIG).
    assert_eq!(tl.at(ms(2_900), "contactor"), "0");
    // The trip is set dominant: RESET at 4.5 s while overloaded does nothing.
    assert_eq!(tl.times_of("fault", "1"), [4_000]);
    assert_eq!(tl.at(ms(4_600), "fault"), "1");
    assert_eq!(tl.times_of("fault", "0")[1..], [6_000]);
    assert_eq!(tl.at(ms(8_000), "starts"), "3");
}

#[test]
fn conveyor_counts_boxes_and_cartons() {
    let tl = conveyor::run();
    // Three full cartons, one pusher stroke of 0.5 s each.
    let pushes = tl.times_of("pusher", "1");
    assert_eq!(pushes.len(), 3);
    for (on, off) in pushes.iter().zip(&tl.times_of("pusher", "0")[1..]) {
        assert_eq!(off - on, 500);
    }
    let left: Vec<&str> = tl.changes("left").into_iter().map(|(_, v)| v).collect();
    assert_eq!(left, ["0", "3", "2", "1", "0"]);
    // The belt stops for every stroke and for good when the order is done.
    assert_eq!(tl.at(ms(10_000), "done"), "1");
    assert_eq!(tl.at(ms(10_000), "motor"), "0");
    // Each carton gets exactly four boxes.
    let counts: Vec<&str> = tl.changes("boxes").into_iter().map(|(_, v)| v).collect();
    assert_eq!(counts.iter().filter(|v| **v == "4").count(), 3);
    assert!(counts.iter().all(|v| ["0", "1", "2", "3", "4"].contains(v)));
}

#[test]
fn batch_weigh_fills_to_target_and_records_the_division_by_zero() {
    let tl = batch_weigh::run();
    assert_eq!(tl.times_of("fast", "1"), [1_000]);
    assert_eq!(tl.times_of("fast", "0")[1..], [2_200]); // net 480 > 450
    assert_eq!(tl.times_of("slow", "0")[1..], [2_600]); // net 500
    assert_eq!(tl.at(ms(2_600), "net"), "500");
    // Settled for 1 s.
    assert_eq!(tl.times_of("done", "1"), [3_600]);
    assert_eq!(tl.at(ms(3_600), "display"), "0500");
    // ENO = FALSE for a negative net weight: the display holds.
    assert_eq!(tl.at(ms(4_500), "ok"), "0");
    assert_eq!(tl.at(ms(4_500), "display"), "0500");
    assert_eq!(tl.at(ms(5_200), "display"), "0000");
    // Target 0: DIV by zero gives 0 and is recorded once per scan.
    assert_eq!(tl.at(ms(5_500), "%"), "0");
    assert_eq!(tl.at(ms(5_700), "faults"), "3");
    let footer = tl.footer_lines().join("\n");
    assert!(
        footer.contains("integer division by zero in BatchWeigher at IL line"),
        "{footer}"
    );
}

#[test]
fn stair_light_holds_ten_seconds_after_the_press() {
    let tl = stair_light::run();
    // The TOF starts timing when the one-scan R_TRIG pulse falls (0.1 s
    // after the press), so the lamp goes off 10.1 s after the last press.
    assert_eq!(tl.times_of("lamp", "1"), [1_000]);
    assert_eq!(tl.times_of("lamp", "0")[1..], [22_100]);
    assert_eq!(tl.times_of("warn", "1"), [9_100, 20_100]);
}

/// The configuration runs Fast every 200 ms and Slow every second, Fast
/// first when both are due; the globals are shared between the programs.
#[test]
fn bottling_runs_two_tasks_at_their_intervals() {
    let tl: Timeline = bottling::run();
    let ran = |t: i64| tl.at(ms(t), "ran").to_string();
    assert_eq!(ran(0), "Fast:Fill Slow:Report");
    assert_eq!(ran(100), "-");
    assert_eq!(ran(200), "Fast:Fill");
    assert_eq!(ran(1000), "Fast:Fill Slow:Report");
    // 6 bottles in the first second (0, 200, ..., 1000 ms): Report saw 6 - 1.
    assert_eq!(tl.at(ms(1000), "rate"), "5");
    // Stopped from 1.5 s to 1.9 s: Fill runs but adds nothing.
    assert_eq!(tl.at(ms(1800), "bottles"), "8");
    assert_eq!(tl.at(ms(3000), "bottles"), "14");
    // The located global %QX0.0 toggles with each fill while running.
    assert_eq!(tl.times_of("valve", "0")[..2], [200, 600]);
}

/// The README's and the guide's host snippet (they quote these lines): one
/// scan with `start` pressed, then 10 ms of simulated time.
#[test]
// The README shows the host's steps one by one, as a host writes them.
#[allow(clippy::field_reassign_with_default)]
fn the_readmes_host_drives_one_scan() {
    use il_examples::readme_motor::Motor;
    let mut ctx = il_std::Cycle::new();
    let mut m = Motor::default();
    m.start = true;
    m.call(&mut ctx); // one scan
    ctx.advance(il_std::TIME::from_ms(10)); // simulated time
    assert!(m.run);
}

/// The recorded waveform, read back, holds what the time-line shows.
#[test]
fn trace_motor_records_every_variable_as_vcd() {
    use il_trace::read::{self, Sample};
    let mut buf = Vec::new();
    let tl = il_examples::trace_motor::record(&mut buf).unwrap();
    let d = read::parse(&buf[..]).unwrap();
    // SCAN is 100 ms: the timescale is 100 ms's coarsest whole unit, ms.
    assert_eq!(d.timescale, Some((1, vcd::TimescaleUnit::MS)));
    let paths: Vec<String> = d.signals.iter().map(|s| s.path.join(".")).collect();
    assert_eq!(
        paths,
        [
            "motor.start",
            "motor.stop",
            "motor.run",
            "motor.starts",
            "motor.edge.CLK",
            "motor.edge.Q"
        ]
    );
    let run = d.signal("motor.run").unwrap();
    let starts = d.signal("motor.starts").unwrap();
    for (t, want_run, want_starts) in [
        (0, 0, 0),
        (200, 1, 1),
        (900, 1, 1),
        (1000, 0, 1),
        (1500, 1, 2),
    ] {
        assert_eq!(run.at(t), Some(&Sample::Bits(want_run)), "run at {t} ms");
        assert_eq!(
            starts.at(t),
            Some(&Sample::Bits(want_starts)),
            "starts at {t} ms"
        );
    }
    // The rising edge lasts one scan.
    let q = d.signal("motor.edge.Q").unwrap();
    assert_eq!(q.at(200), Some(&Sample::Bits(1)));
    assert_eq!(q.at(300), Some(&Sample::Bits(0)));
    assert!(tl.to_string().contains("press start again"));
}
