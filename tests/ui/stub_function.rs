// Stub: a FUNCTION whose body has a type mistake (ADD of DINT and REAL);
// `main` calls it. Only the IL error may appear.
use il_std::Cycle;

il_macros::il!(r#"
FUNCTION SCALE : INT
VAR_INPUT
    raw : DINT;
    gain : REAL;
END_VAR
    LD raw
    ADD gain
    ST SCALE
END_FUNCTION
"#);

fn main() {
    let mut ctx = Cycle::new();
    let _: i16 = SCALE(&mut ctx, 1, 2.0);
}
