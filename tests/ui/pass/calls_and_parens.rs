// Accepted IL compiles: a formal CAL with outputs (=>), CTUD, nested
// parentheses, JMPNC/RETC, a label on an instruction line, a FUNCTION
// with a formal call and one used as an operator, and a PROGRAM.
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

fn main() {
    let mut ctx = Cycle::new();
    let mut p = Main::default();
    p.up = true;
    p.call(&mut ctx);
    assert_eq!(p.n, 1);
    assert_eq!(AVG2(&mut ctx, 4, 8), 6);
}
