// Binding I/O through typed addresses and generated accessors: a value of
// the wrong type does not compile (it used to be a byte offset and a u16).

mod tank {
    il_macros::il!(r#"
PROGRAM Tank
VAR
    level AT %IW1 : INT;
    pump  AT %QX0.0 : BOOL;
END_VAR
    LD   level
    GT   500
    ST   pump
END_PROGRAM
"#);
}

fn main() {
    use il_std::addr::{iw, ix};
    let mut ctx = il_std::Cycle::new();
    // %IX0.0 holds a BOOL.
    ctx.io.set(ix(0, 0), 1);
    // %IW1 as a WORD is unsigned: a negative INT needs `.int()`.
    ctx.io.set(iw(1), -5i16);
    // `level` is an INT.
    tank::Tank::set_io_level(&mut ctx, 1.5);
}
