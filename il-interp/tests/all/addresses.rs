//! Located variables (`AT %IX0.0`, `%IW2`, `%QD1`, `%MB3`) and direct
//! addresses as operands, read and written in the process image exactly
//! where generated code reads and writes them (byte offsets, bit numbers,
//! little-endian words, signed types, REAL bits), also set by a host.

use il_codegen::diag::SourceFile;
use il_codegen::ir::types::Elem;
use il_interp::{Machine, Value, load};
use il_std::{Area, Cycle};

const IO: &str = "\
FUNCTION_BLOCK Lamp
VAR_INPUT sw : BOOL; END_VAR
VAR_OUTPUT lit AT %QX3.7 : BOOL; END_VAR
    LD sw
    ST lit
END_FUNCTION_BLOCK

PROGRAM Io
VAR
    start AT %IX0.0 : BOOL;
    level AT %IW2 : INT;
    speed AT %ID2 : REAL;
    motor AT %QX0.1 : BOOL;
    out AT %QW1 : INT;
    mark AT %MB3 : SINT;
    lamp : Lamp;
    copy : WORD;
    bit5 : BOOL;
    f : REAL;
END_VAR
    LD start
    ST motor
    LD level
    MUL 2
    ST out
    LD %IW2
    ST copy
    LD %IX1.5
    ST bit5
    ST %QX5.0
    LD speed
    MUL 2.0
    ST f
    LD -3
    ST mark
    LD %MB3
    ST %QB7
    CAL lamp(sw := start)
END_PROGRAM
";

fn io() -> Machine {
    let p = load(&SourceFile::new("io.il", IO)).unwrap();
    Machine::new(&p, "Io").unwrap()
}

#[test]
fn the_process_image_bit_for_bit() {
    let mut m = io();
    let mut ctx = Cycle::new();
    ctx.io.set_bit(Area::Input, 0, 0, true);
    // %IW2 is bytes 4 and 5 (word 2), little-endian: -300 = 0xFED4.
    ctx.io.set_byte(Area::Input, 4, 0xD4);
    ctx.io.set_byte(Area::Input, 5, 0xFE);
    ctx.io.set_bit(Area::Input, 1, 5, true);
    ctx.io.set_dword(Area::Input, 8, 1.5f32.to_bits());
    m.scan(&mut ctx).unwrap();
    assert!(ctx.io.bit(Area::Output, 0, 1), "motor at %QX0.1");
    // -300 * 2 = -600 = 0xFDA8 at %QW1 (bytes 2 and 3).
    assert_eq!(ctx.io.byte(Area::Output, 2), 0xA8);
    assert_eq!(ctx.io.byte(Area::Output, 3), 0xFD);
    assert_eq!(m.get("copy"), Some(il_interp::int(0xFED4, Elem::WORD)));
    assert_eq!(m.get("bit5"), Some(Value::Bool(true)));
    assert!(ctx.io.bit(Area::Output, 5, 0));
    assert_eq!(m.get("f"), Some(Value::Real(3.0)));
    assert_eq!(ctx.io.byte(Area::Memory, 3), 0xFD, "SINT -3 at %MB3");
    assert_eq!(ctx.io.byte(Area::Output, 7), 0xFD, "%MB3 copied to %QB7");
    assert!(
        ctx.io.bit(Area::Output, 3, 7),
        "a located output of an FB instance"
    );
    // The instance holds no copy of located variables.
    assert_eq!(m.get("motor"), None);
}

#[test]
fn a_host_sets_and_reads_addresses_and_located_variables() {
    let mut m = io();
    let mut ctx = Cycle::new();
    for (name, text) in [("%IX0.0", "TRUE"), ("level", "-300"), ("%IX1.5", "1")] {
        let p = m.lookup(name).unwrap();
        let v = m.parse_for(&p, text).unwrap();
        m.set_at(&mut ctx, &p, v).unwrap();
    }
    assert!(ctx.io.bit(Area::Input, 0, 0));
    assert_eq!(ctx.io.word(Area::Input, 4), 0xFED4);
    let w = m.lookup("%IW2").unwrap();
    assert_eq!(
        w.ty.to_string(),
        "WORD",
        "an address has the type of its size"
    );
    assert_eq!(m.get_at(&ctx, &w), il_interp::int(0xFED4, Elem::WORD));
    let lv = m.lookup("level").unwrap();
    assert_eq!(m.get_at(&ctx, &lv), il_interp::int(-300, Elem::INT));
    m.scan(&mut ctx).unwrap();
    for (name, want) in [
        ("motor", Value::Bool(true)),
        ("%QX0.1", Value::Bool(true)),
        ("out", il_interp::int(-600, Elem::INT)),
        ("%QW1", il_interp::int(0xFDA8, Elem::WORD)),
        ("%QB2", il_interp::int(0xA8, Elem::BYTE)),
        ("%QX5.0", Value::Bool(true)),
        ("mark", il_interp::int(-3, Elem::SINT)),
        ("%QX3.7", Value::Bool(true)),
    ] {
        let p = m.lookup(name).unwrap();
        assert_eq!(m.get_at(&ctx, &p), want, "{name}");
    }
    assert!(m.watchable().contains(&"level".to_string()));
    assert!(!m.watchable().contains(&"lamp".to_string()));
}

#[test]
fn wrong_addresses_are_refused() {
    let m = io();
    for (text, msg) in [
        ("%IX0.8", "bit 8"),
        ("%IW99999", "outside the process image"),
        ("%Z3", "I, Q or M"),
        ("%IW", "expected a number"),
        ("motor.x", "has no members"),
        ("%IW2 x", "not a direct address"),
    ] {
        let e = m.lookup(text).unwrap_err();
        assert!(e.contains(msg), "{text}: {e}");
    }
    let p = m.lookup("%IW2").unwrap();
    assert!(m.parse_for(&p, "-1").is_err(), "a WORD is unsigned");
}

#[test]
fn run_time_errors_say_where() {
    // A loop without end: the step limit error names the file, line and column.
    let src = "PROGRAM Spin\nVAR n : INT; END_VAR\nagain:\n    LD n\n    JMP again\nEND_PROGRAM\n";
    let p = load(&SourceFile::new("spin.il", src)).unwrap();
    let mut m = Machine::new(&p, "Spin").unwrap();
    let e = m.scan(&mut Cycle::new()).unwrap_err();
    assert!(e.starts_with("spin.il:"), "{e}");
    assert!(e.contains(": in Spin: more than"), "{e}");
    let loc: Vec<&str> = e.splitn(4, ':').collect();
    assert!(matches!(loc[1], "3" | "4" | "5"), "{e}");
    assert!(loc[2].parse::<u32>().is_ok_and(|c| c >= 1), "{e}");
}
