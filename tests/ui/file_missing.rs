// Macro input: the file form names an IL file that does not exist.
il_macros::il!(file = "no/such.il");

fn main() {}
