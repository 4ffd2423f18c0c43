// Macro input: a number instead of an IL string or `file = "..."`.
il_macros::il!(42);

fn main() {}
