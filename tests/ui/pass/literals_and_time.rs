// Accepted IL compiles: typed and based literals, reals with exponent,
// durations, strings with $ escapes, TIME arithmetic.
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

fn main() {
    let mut ctx = Cycle::new();
    let mut l = Lits::default();
    l.call(&mut ctx);
    assert_eq!(l.w, 0xFFFF);
    assert_eq!(l.i, -5);
    assert_eq!(l.u, 0xA5);
    assert!(l.b);
    assert_eq!(l.by, 0xA5);
}
