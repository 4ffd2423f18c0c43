// Accepted programs: each former pass case in its own module (its IL, its Rust
// code, its `main`); the `main` of this file runs them all, in order.

// Accepted IL compiles: a function block with a timer, an edge, a counter,
// labels, deferred parentheses and a user FUNCTION, called from Rust.
mod accepted_programs {
use il_std::Cycle;

il_macros::il!(r#"
FUNCTION SCALE : INT
VAR_INPUT
    raw : INT;
    factor : INT;
END_VAR
    LD raw
    MUL factor
    ST SCALE
END_FUNCTION

FUNCTION_BLOCK Station
VAR_INPUT
    start : BOOL;
    stop : BOOL;
    part : BOOL;
    sensor : INT;
END_VAR
VAR_OUTPUT
    run : BOOL;
    parts : INT;
    value : INT;
    alarm : BOOL;
END_VAR
VAR
    settle : TON;
    edge : R_TRIG;
    counter : CTU;
    ff : SR;
END_VAR
VAR CONSTANT
    BATCH : INT := 12;
END_VAR
    LD   start
    OR   run
    ANDN stop
    ST   run
    IN   settle
    LD   T#500ms
    PT   settle
    LD   part
    AND( settle.Q
    OR   alarm
    )
    CLK  edge
    LD   edge.Q
    CU   counter
    LD   BATCH
    PV   counter
    LD   counter.CV
    ST   parts
    LD   sensor
    SCALE 10
    LIMIT 0, 1000
    ST   value
    GT   900
    JMPCN done
    LD   TRUE
    S1   ff
done:
    LD   ff.Q1
    ST   alarm
END_FUNCTION_BLOCK
"#);

pub fn main() {
    let mut ctx = Cycle::new();
    let mut s = Station::default();
    s.start = true;
    s.sensor = 95;
    s.call(&mut ctx);
    assert!(s.run);
    assert_eq!(s.value, 950);
    assert!(s.alarm);
    assert_eq!(SCALE(&mut ctx, 3, 4), 12);
}
}

// Accepted IL compiles: a formal CAL with outputs (=>), CTUD, nested
// parentheses, JMPNC/RETC, a label on an instruction line, a FUNCTION
// with a formal call and one used as an operator, and a PROGRAM.
mod calls_and_parens {
use il_std::Cycle;

il_macros::il!(r#"
FUNCTION AVG2 : INT
VAR_INPUT
    a : INT;
    b : INT;
END_VAR
    LD a
    ADD b
    DIV 2
    ST AVG2
END_FUNCTION

PROGRAM Main
VAR
    up : BOOL;
    down : BOOL;
    cnt : CTUD;
    top : BOOL;
    n : INT;
    m : INT;
    x : BOOL;
    y : BOOL;
    z : BOOL;
END_VAR
    CAL cnt(CU := up, CD := down, PV := 10, QU => top, CV => n)
    LD x
    AND( y
    OR( z
    AND(
        LD TRUE
        XOR x
    )
    )
    )
    ST z
    LD n
    GT 5
    JMPNC small
    LD n
    AVG2 4
    ST m
    RET
small: LD n
    ST m
    AVG2(
        a := n,
        b := 6
    )
    ST m
    LD top
    RETC
END_PROGRAM
"#);

pub fn main() {
    let mut ctx = Cycle::new();
    let mut p = Main::default();
    p.up = true;
    p.call(&mut ctx);
    assert_eq!(p.n, 1);
    assert_eq!(AVG2(&mut ctx, 4, 8), 6);
}
}

// Accepted IL compiles: keywords and names in any case, operator names (R1,
// IN, PV) as variable names, as the standard's STACK_INT does.
mod case_insensitive {
use il_std::Cycle;

il_macros::il!(r#"
function_block Latch
var_input
    Set : BOOL;
    R1 : BOOL;
    IN : INT;
end_var
var_output
    Out : BOOL;
    PV : INT;
end_var
    ld SET
    or out
    andn r1
    st OUT
    Ld in
    St pv
end_function_block
"#);

pub fn main() {
    let mut ctx = Cycle::new();
    let mut l = Latch::default();
    l.Set = true;
    l.IN = 7;
    l.call(&mut ctx);
    assert!(l.Out);
    assert_eq!(l.PV, 7);
}
}

// A configuration with globals, externals and in-outs compiles, and the
// host drives it with the time in the cycle context.
mod configuration {
il_macros::il!(r#"
FUNCTION_BLOCK Bump
VAR_IN_OUT n : INT; END_VAR
VAR_EXTERNAL bumps : INT; END_VAR
    LD n
    ADD 1
    ST n
    LD bumps
    ADD 1
    ST bumps
END_FUNCTION_BLOCK

PROGRAM Main
VAR_EXTERNAL bumps : INT; END_VAR
VAR b : Bump; x : INT; END_VAR
    CAL b(n := x)
END_PROGRAM

CONFIGURATION Plant
VAR_GLOBAL bumps : INT; END_VAR
TASK t (INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM m WITH t : Main;
END_CONFIGURATION
"#);

pub fn main() {
    let mut ctx = il_std::Cycle::new();
    let mut plant = Plant::default();
    for ms in [0, 10, 20] {
        ctx.set_now(il_std::TIME::from_ms(ms));
        plant.run(&mut ctx);
    }
    assert_eq!((plant.bumps, plant.m.x), (3, 3));
}
}

// Accepted IL compiles: typed and based literals, reals with exponent,
// durations, strings with $ escapes, TIME arithmetic.
mod literals_and_time {
use il_std::Cycle;

il_macros::il!(r#"
FUNCTION_BLOCK Lits
VAR_OUTPUT
    w : WORD;
    i : INT;
    u : UINT;
    r : REAL;
    lr : LREAL;
    t : TIME;
    s : STRING;
    b : BOOL;
    by : BYTE;
END_VAR
    LD 16#FF_FF
    ST w
    LD INT#-5
    ST i
    LD UINT#16#A5
    ST u
    LD 1.5E-3
    ST r
    LD LREAL#2.5
    ST lr
    LD T#1m_30s
    ADD T#500ms
    ST t
    LD 'it$'s $N ok'
    ST s
    LD BOOL#1
    ST b
    LD 2#1010_0101
    ST by
END_FUNCTION_BLOCK
"#);

pub fn main() {
    let mut ctx = Cycle::new();
    let mut l = Lits::default();
    l.call(&mut ctx);
    assert_eq!(l.w, 0xFFFF);
    assert_eq!(l.i, -5);
    assert_eq!(l.u, 0xA5);
    assert!(l.b);
    assert_eq!(l.by, 0xA5);
}
}

// A FUNCTION_BLOCK named `i16` (a legal IEC identifier) must not hide Rust's
// i16 in the generated code: the struct is emitted as `i16_`.
mod pou_named_like_rust_type {
il_macros::il!(r#"
FUNCTION_BLOCK i16
VAR_OUTPUT
    n : INT;
END_VAR
    LD 3
    ST n
END_FUNCTION_BLOCK
"#);

pub fn main() {
    let mut ctx = il_std::Cycle::new();
    let mut b = i16_::default();
    b.call(&mut ctx);
    let n: i16 = b.n;
    assert_eq!(n, 3);
}
}

// Accepted IL compiles: IL names that are Rust keywords or reserved names
// (loop, match, self, fn, crate), and a FUNCTION called `Default`.
mod rust_keywords {
use il_std::Cycle;

il_macros::il!(r#"
FUNCTION Default : INT
VAR_INPUT
    a : INT;
END_VAR
    LD a
    ST Default
END_FUNCTION

FUNCTION_BLOCK Names
VAR_INPUT
    go : BOOL;
    loop : BOOL;
END_VAR
VAR_OUTPUT
    match : BOOL;
    self : BOOL;
END_VAR
VAR
    fn : INT;
    crate : INT;
END_VAR
    LD go
    AND loop
    ST match
    ST self
    LD fn
    ADD crate
    Default
    ST fn
END_FUNCTION_BLOCK
"#);

pub fn main() {
    let mut ctx = Cycle::new();
    let mut n = Names::default();
    n.call(&mut ctx);
    assert!(!n.r#match);
}
}

// `il!(..., serde)` derives serde's traits on the generated types.
mod serde_flag {
il_macros::il!(r#"
TYPE Mode : (Idle, Run); END_TYPE
FUNCTION_BLOCK Counter
VAR RETAIN n : DINT; END_VAR
VAR mode : Mode; END_VAR
    LD n
    ADD 1
    ST n
END_FUNCTION_BLOCK
"#, serde);

fn is_serde<T: serde::Serialize + for<'de> serde::Deserialize<'de>>() {}

pub fn main() {
    is_serde::<Mode>();
    is_serde::<Counter>();
    is_serde::<Counter__Retain>();
}
}

fn main() {
    accepted_programs::main();
    calls_and_parens::main();
    case_insensitive::main();
    configuration::main();
    literals_and_time::main();
    pou_named_like_rust_type::main();
    rust_keywords::main();
    serde_flag::main();
}
