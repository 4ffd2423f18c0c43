//! A hand-written block offering every kind of value, recorded over scans
//! and read back with the `vcd` crate's parser.

use il_std::trace::{AsValue, Value, Visit, Visitor};
use il_std::{Cycle, STRING, TIME, TON};
use il_trace::read::{self, Sample};
use il_trace::{AtomicFile, Recorder};

#[derive(Default)]
struct Plant {
    run: bool,
    level: i16,
    count: u32,
    flow: f32,
    state: i64,
    name: STRING<16>,
    table: [[i8; 2]; 2],
    delay: TON,
    pumps: [TON; 2],
}

impl Visit for Plant {
    fn visit(&self, v: &mut dyn Visitor) {
        v.var("run", "BOOL", self.run.as_value());
        v.var("level", "INT", self.level.as_value());
        v.var("count", "UDINT", self.count.as_value());
        v.var("flow", "REAL", self.flow.as_value());
        let names = ["Idle", "Filling", "Draining"];
        v.var(
            "state",
            "TankState",
            Value::Enum {
                value: self.state,
                name: names[self.state as usize],
            },
        );
        v.var("name", "STRING[16]", self.name.as_value());
        for (i, row) in self.table.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                v.elem("table", &[i as i64, 1 + j as i64], "SINT", x.as_value());
            }
        }
        v.enter("delay");
        self.delay.visit(v);
        v.leave();
        for (i, p) in self.pumps.iter().enumerate() {
            v.enter_elem("pumps", &[1 + i as i64]);
            p.visit(v);
            v.leave();
        }
    }
}

/// Runs 6 scans of 10 ms, changing the plant, and returns the dump and
/// the expected values of some variables per scan.
/// Per scan: run, level, flow, state, delay.ET (ns), table[1,1].
type Expected = (bool, i16, f32, i64, i64, i8);

fn record() -> (Vec<u8>, Vec<Expected>) {
    let mut ctx = Cycle::new();
    let mut p = Plant::default();
    p.delay.PT = TIME::from_ms(20);
    let mut buf = Vec::new();
    let mut rec = Recorder::new(&mut buf, "plant", TIME::from_ms(10)).unwrap();
    let mut expect = Vec::new();
    for k in 0..6i16 {
        p.run = k % 2 == 1;
        p.level = -3 * k;
        p.count = u32::MAX - k as u32;
        p.flow = k as f32 * 0.5;
        p.state = (k % 3) as i64;
        p.name = STRING::from_str_truncating(if k < 3 { "a b" } else { "c\\d" }).0;
        p.table[1][0] = -(k as i8);
        p.delay.IN = k >= 1;
        p.delay.call(&mut ctx);
        rec.sample(ctx.now(), &p).unwrap();
        expect.push((p.run, p.level, p.flow, p.state, p.delay.ET.0, p.table[1][0]));
        ctx.advance(TIME::from_ms(10));
    }
    rec.finish().unwrap();
    (buf, expect)
}

#[test]
fn values_read_back_at_every_scan() {
    let (buf, expect) = record();
    let d = read::parse(&buf[..]).unwrap();
    assert_eq!(d.timescale, Some((1, vcd::TimescaleUnit::MS)));
    let s = |p: &str| d.signal(p).unwrap_or_else(|| panic!("no {p}"));
    assert_eq!(s("plant.run").var_type, "wire");
    assert_eq!(s("plant.run").width, 1);
    assert_eq!(s("plant.level").width, 16);
    assert_eq!(s("plant.count").width, 32);
    assert_eq!(s("plant.flow").var_type, "real");
    assert_eq!(s("plant.state").var_type, "integer");
    assert_eq!(s("plant.delay.ET").var_type, "integer");
    assert!(d.signal("plant.pumps[2].Q").is_some());
    for (k, (run, level, flow, state, et_ns, t10)) in expect.iter().enumerate() {
        let t = 10 * k as u64;
        assert_eq!(
            s("plant.run").at(t),
            Some(&Sample::Bits(*run as u64)),
            "run at {t}"
        );
        assert_eq!(
            s("plant.level").at(t).unwrap().signed(16),
            Some(*level as i64)
        );
        assert_eq!(s("plant.flow").at(t), Some(&Sample::Real(*flow as f64)));
        assert_eq!(s("plant.state").at(t), Some(&Sample::Bits(*state as u64)));
        // TIME counts the timescale unit (ms).
        assert_eq!(
            s("plant.delay.ET").at(t),
            Some(&Sample::Bits((et_ns / 1_000_000) as u64))
        );
        assert_eq!(
            s("plant.table[1,1]").at(t).unwrap().signed(8),
            Some(*t10 as i64)
        );
        let name = if k < 3 { "a\\x20b" } else { "c\\x5cd" };
        assert_eq!(s("plant.name").at(t), Some(&Sample::Str(name.into())));
    }
    // Only changes are written: `count` changes every scan, `pumps` never.
    assert_eq!(s("plant.count").changes.len(), 6);
    assert_eq!(s("plant.pumps[1].ET").changes.len(), 1);
    // Each enumeration change names the value.
    let notes: Vec<&str> = d.comments.iter().map(|(_, c)| c.as_str()).collect();
    assert!(notes.contains(&"state = Filling"), "{notes:?}");
    assert!(
        d.comments.contains(&(20, "state = Draining".to_string())),
        "{notes:?}"
    );
}

#[test]
fn timescale_follows_the_step() {
    use vcd::TimescaleUnit::*;
    assert_eq!(il_trace::timescale(TIME::from_ms(10)), (MS, 1_000_000));
    assert_eq!(il_trace::timescale(TIME::from_ms(2000)), (S, 1_000_000_000));
    assert_eq!(il_trace::timescale(TIME(1500)), (NS, 1));
    assert_eq!(il_trace::timescale(TIME(0)), (NS, 1));
    assert_eq!(il_trace::timescale(TIME(250_000)), (US, 1_000));
}

#[test]
fn a_changed_set_of_variables_is_an_error() {
    let mut buf = Vec::new();
    let mut rec = Recorder::new(&mut buf, "x", TIME::from_ms(1)).unwrap();
    rec.sample_with(TIME(0), |v| v.var("a", "BOOL", Value::Bool(true)))
        .unwrap();
    let e = rec
        .sample_with(TIME::from_ms(1), |v| {
            v.var("a", "BOOL", Value::Bool(true));
            v.var("b", "BOOL", Value::Bool(true));
        })
        .unwrap_err();
    assert!(e.to_string().contains("changed"), "{e}");
    let e = rec
        .sample_with(TIME::from_ms(2), |v| {
            v.var("a", "INT", Value::Int { value: 1, bits: 16 })
        })
        .unwrap_err();
    assert!(e.to_string().contains("type"), "{e}");
    rec.sample_with(TIME::from_ms(3), |v| v.var("a", "BOOL", Value::Bool(false)))
        .unwrap();
    let e = rec
        .sample_with(TIME::from_ms(2), |v| v.var("a", "BOOL", Value::Bool(true)))
        .unwrap_err();
    assert!(e.to_string().contains("backwards"), "{e}");
}

#[test]
fn atomic_file_appears_only_on_commit() {
    let dir = std::env::temp_dir().join(format!("il-trace-atomic-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("t.vcd");
    std::fs::write(&path, "old").unwrap();
    {
        let mut f = AtomicFile::create(&path).unwrap();
        let mut rec = Recorder::new(&mut f, "x", TIME::from_ms(1)).unwrap();
        rec.sample_with(TIME(0), |v| v.var("a", "BOOL", Value::Bool(true)))
            .unwrap();
        rec.finish().unwrap();
        // Dropped without commit: the old file stays, no temporary is left.
    }
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "old");
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
    let mut f = AtomicFile::create(&path).unwrap();
    let mut rec = Recorder::new(&mut f, "x", TIME::from_ms(1)).unwrap();
    rec.sample_with(TIME(0), |v| v.var("a", "BOOL", Value::Bool(true)))
        .unwrap();
    rec.finish().unwrap();
    f.commit().unwrap();
    let d = read::parse(std::io::BufReader::new(std::fs::File::open(&path).unwrap())).unwrap();
    assert_eq!(d.signal("x.a").unwrap().at(0), Some(&Sample::Bits(1)));
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn enumeration_comments_name_the_path() {
    let mut buf = Vec::new();
    let mut rec = Recorder::new(&mut buf, "plant", TIME::from_ms(1)).unwrap();
    for (k, name) in ["Idle", "Idle", "Filling"].iter().enumerate() {
        rec.sample_with(TIME::from_ms(k as i64), |v| {
            v.enter("tank");
            v.var(
                "state",
                "TankState",
                Value::Enum {
                    value: k as i64,
                    name,
                },
            );
            v.leave();
        })
        .unwrap();
    }
    rec.finish().unwrap();
    let d = read::parse(&buf[..]).unwrap();
    assert_eq!(
        d.comments,
        [
            (0, "tank.state = Idle".to_string()),
            (1, "tank.state = Idle".to_string()),
            (2, "tank.state = Filling".to_string())
        ]
    );
    assert_eq!(d.signal("plant.tank.state").unwrap().changes.len(), 3);
}
