//! The front end never panics, whatever it is fed, and its cost grows
//! linearly with the input.
//!
//! A deterministic property test (a hand-written xorshift PRNG, fixed seeds)
//! feeds well over 100,000 inputs through `syntax::parse`, and everything that
//! comes out through `render`, `render_short` and `to_json`: random bytes,
//! token soup from an IL vocabulary, and mutations of the shared corpus and of
//! a few built-in valid programs. `fuzz/` holds the same target for cargo-fuzz.

use std::path::PathBuf;
use std::time::Instant;

use il_codegen::ast::parse;
use il_codegen::ast::{CompilationUnit, Item, Span};
use il_codegen::diag::{Diagnostic, SourceFile, render, render_short, to_json};

/// xorshift64* (Vigna): small, fast, good enough for test inputs.
struct Rng(u64);

impl Rng {
    fn new(seed: u64) -> Self {
        Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }
    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// Uniform in `0..n` (n > 0).
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn pick<T: Copy>(&mut self, xs: &[T]) -> T {
        xs[self.below(xs.len())]
    }
    fn chance(&mut self, percent: usize) -> bool {
        self.below(100) < percent
    }
}

#[rustfmt::skip]
const VOCAB: &[&str] = &[
    // operators and their modifiers
    "LD", "LDN", "ST", "STN", "S", "R", "S1", "R1", "AND", "ANDN", "&", "&N", "OR", "ORN", "XOR",
    "XORN", "NOT", "ADD", "SUB", "MUL", "DIV", "MOD", "GT", "GE", "EQ", "NE", "LE", "LT", "JMP",
    "JMPC", "JMPCN", "CAL", "CALC", "CALCN", "RET", "RETC", "RETCN", "CLK", "CU", "CD", "PV", "IN",
    "PT", "AND(", "OR(", "ADD(", "MUL(",
    // keywords
    "PROGRAM", "END_PROGRAM", "FUNCTION", "END_FUNCTION", "FUNCTION_BLOCK", "END_FUNCTION_BLOCK",
    "VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_EXTERNAL", "VAR_GLOBAL", "VAR_TEMP",
    "CONSTANT", "RETAIN", "END_VAR", "AT", "TYPE", "END_TYPE", "STRUCT", "END_STRUCT", "ARRAY",
    "OF", "STRING", "CONFIGURATION", "END_CONFIGURATION", "RESOURCE", "ON", "END_RESOURCE", "TASK",
    "WITH", "INTERVAL", "PRIORITY", "R_EDGE", "F_EDGE", "BOOL", "INT", "REAL", "TIME", "TON", "CTU",
    "TRUE", "FALSE", "IF", "THEN", "END_IF", "INITIAL_STEP", "END_STEP",
    // punctuation
    "(", ")", ":=", "=>", ":", ";", ",", ".", "..", "[", "]", "#", "-", "+", "=", "<>", "*", "/",
    "(*", "*)", "(* comment *)", "//", "\"", "'", "$",
    // operands and literals
    "%IX1.0", "%QW3", "%MD4.23", "%I*", "%Q0.0", "T#1s", "T#1h_2m", "TIME#-5ms", "t#500ms", "16#FF",
    "2#1010_1010", "8#777", "1.5E3", "-12e-5", "INT#5", "BOOL#1", "'str'", "'it''s $N $$'",
    "\"wide\"", "''", "DT#2001-04-09-11:36:15.20", "TOD#11:36:15", "D#2001-04-09", "0", "1", "-1",
    "4294967296999999", "x", "motor", "Motor.Q", "fb.out", "arr[1]", "arr[i, 2]", "_x", "a__b",
    "lbl:", "END:", "start:", "ä", "名前", "\u{0}", "\u{1b}[31m", "\u{feff}",
    // layout
    "\n", "\n", "\n", "\r\n", "\t",
];

const VALID: &[&str] = &[
    "PROGRAM main\nVAR\n    a, b : BOOL;\n    n : INT := 0;\nEND_VAR\n    LD a\n    AND b\n    ST b\n    LD n\n    ADD 1\n    ST n\nEND_PROGRAM\n",
    "FUNCTION_BLOCK Blink\nVAR_INPUT en : BOOL; END_VAR\nVAR_OUTPUT q : BOOL; END_VAR\nVAR t : TON; END_VAR\n    CAL t(\n        IN := en,\n        PT := T#500ms\n    )\n    LD t.Q\n    JMPCN done\n    LD q\n    NOT\n    ST q\ndone:\n    RET\nEND_FUNCTION_BLOCK\n",
    "FUNCTION Clamp : INT\nVAR_INPUT x, lo, hi : INT; END_VAR\n    LD x\n    LT lo\n    JMPC low\n    LD x\n    GT hi\n    JMPC high\n    LD x\n    ST Clamp\n    RET\nlow: LD lo\n    ST Clamp\n    RET\nhigh: LD hi\n    ST Clamp\nEND_FUNCTION\n",
    "PROGRAM p\nVAR x AT %IX0.1 : BOOL; y AT %QX0.0 : BOOL; z : REAL; END_VAR\n    LD x\n    AND( y\n    OR( x\n    )\n    )\n    ST y\n    LD 2.5\n    MUL( z\n    ADD 1.0\n    )\n    ST z\nEND_PROGRAM\n\nCONFIGURATION c\n    TASK t (INTERVAL := T#10ms, PRIORITY := 1);\n    PROGRAM i WITH t : p;\nEND_CONFIGURATION\n",
];

fn corpus() -> Vec<String> {
    let dir = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/corpus"));
    let Ok(entries) = std::fs::read_dir(&dir) else {
        println!(
            "corpus not found at {}: mutating only the built-in programs",
            dir.display()
        );
        return Vec::new();
    };
    let mut files: Vec<PathBuf> = entries
        .flatten()
        .map(|e| e.path())
        .filter(|p| {
            p.extension()
                .is_some_and(|e| e == "il" || e == "txt" || e == "test")
        })
        .filter(|p| !p.ends_with("SOURCES.txt"))
        .collect();
    files.sort();
    files
        .iter()
        .filter_map(|p| std::fs::read(p).ok())
        .map(|b| String::from_utf8_lossy(&b).into_owned())
        .collect()
}

/// Everything a front end does with a file: parse, then render every way.
fn exercise(name: &str, text: String) -> (CompilationUnit, Vec<Diagnostic>) {
    exercise_with(name, text, true)
}

/// Parse, and when `show` render the first diagnostics every way.
fn exercise_with(name: &str, text: String, show: bool) -> (CompilationUnit, Vec<Diagnostic>) {
    let file = SourceFile::new(name, text);
    let (unit, diags) = parse(&file);
    if !show {
        return (unit, diags);
    }
    // Rendering costs ~25 µs a diagnostic in a debug build, more than
    // parsing: render the first two fully, the JSON (which renders again) of
    // the first only.
    let shown = &diags[..diags.len().min(2)];
    let rendered = render(&file, shown, false);
    assert!(
        shown.is_empty() || rendered.contains("[IL"),
        "no code in {rendered:?}"
    );
    for d in shown {
        let _ = render_short(&file, d);
    }
    if let Some(d) = diags.first() {
        let j = to_json(&file, d);
        assert!(j.starts_with("{\"file\":") && j.ends_with('}') && !j.contains('\n'));
    }
    (unit, diags)
}

/// A diagnostic at random, often invalid, spans (short ones: a span over the
/// whole file costs the renderer a line per line), so that the renderers meet
/// every odd text whatever the parser reports.
fn probe_diag(rng: &mut Rng, text: &str) -> Diagnostic {
    let n = text.len() as u32 + 4;
    let mut span = || {
        let lo = rng.next() as u32 % n;
        let hi = if rng.chance(10) {
            rng.next() as u32 % n
        } else {
            lo + rng.below(40) as u32
        };
        Span { lo, hi }
    };
    let (primary, other) = (span(), span());
    Diagnostic::error("IL0000", primary, "probe")
        .with_label("label")
        .with_secondary(other, "other")
        .with_note("note")
        .with_help("help")
}

fn random_bytes(rng: &mut Rng) -> String {
    let len = rng.below(64);
    let bytes: Vec<u8> = (0..len)
        .map(|_| {
            if rng.chance(70) {
                // Mostly printable ASCII and line breaks: these reach further into the parser.
                rng.pick(b" \n\t()*:=;,.#%'\"$&_-+ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefxyz0123456789")
            } else {
                rng.next() as u8
            }
        })
        .collect();
    String::from_utf8_lossy(&bytes).into_owned()
}

fn token_soup(rng: &mut Rng) -> String {
    let mut s = String::new();
    if rng.chance(60) {
        s.push_str(rng.pick(&[
            "PROGRAM p\n",
            "FUNCTION_BLOCK fb\nVAR x : BOOL; END_VAR\n",
            "FUNCTION f : INT\n",
        ]));
    }
    for _ in 0..rng.below(20) {
        s.push_str(rng.pick(VOCAB));
        s.push_str(rng.pick(&[" ", " ", " ", "\n", "", "\t", "  "]));
    }
    if rng.chance(50) {
        s.push_str(rng.pick(&[
            "\nEND_PROGRAM\n",
            "\nEND_FUNCTION_BLOCK\n",
            "\nEND_FUNCTION\n",
            "",
        ]));
    }
    s
}

/// Byte positions of `s` rounded down to char boundaries.
fn boundary(s: &str, mut i: usize) -> usize {
    i = i.min(s.len());
    while !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

fn mutate(rng: &mut Rng, src: &str) -> String {
    let mut s = src.to_string();
    for _ in 0..1 + rng.below(4) {
        let a = boundary(&s, rng.below(s.len() + 1));
        let b = boundary(&s, a + rng.below(24));
        match rng.below(6) {
            0 => s.replace_range(a..b, ""), // delete
            1 => {
                // duplicate
                let dup = s[a..b].to_owned();
                s.insert_str(a, &dup);
            }
            2 => s.insert_str(a, rng.pick(VOCAB)), // insert a token
            3 => s.truncate(a),                    // truncate
            4 => {
                // swap two ranges
                let c = boundary(&s, rng.below(s.len() + 1));
                let d = boundary(&s, c + rng.below(24));
                if b <= c {
                    let (x, y) = (s[a..b].to_string(), s[c..d].to_string());
                    s.replace_range(c..d, &x);
                    s.replace_range(a..b, &y);
                }
            }
            _ => {
                // flip one byte to another ASCII byte
                if a < s.len() && s.as_bytes()[a].is_ascii() {
                    let c = (rng.below(95) as u8 + 32) as char;
                    s.replace_range(a..a + 1, &c.to_string());
                }
            }
        }
    }
    s
}

#[test]
fn no_input_makes_the_front_end_panic() {
    let start = Instant::now();
    let corpus = corpus();
    let sources: Vec<&str> = VALID
        .iter()
        .copied()
        .chain(corpus.iter().map(String::as_str))
        .collect();
    let mut rng = Rng::new(0x1EC6_1131);
    let mut count = 0usize;
    let mut with_diags = 0usize;
    const ROUNDS: usize = 36_000;
    for i in 0..ROUNDS {
        let inputs = [random_bytes(&mut rng), token_soup(&mut rng), {
            // Parsing costs ~1.5 µs a byte in a debug build: mostly mutate a
            // window of a few lines, the whole file one time in 300.
            let src = rng.pick(&sources);
            if rng.below(300) != 0 {
                let lo = boundary(src, rng.below(src.len()));
                let hi = boundary(src, lo + 30 + rng.below(120));
                mutate(&mut rng, &src[lo..hi])
            } else {
                mutate(&mut rng, src)
            }
        }];
        for (k, text) in inputs.into_iter().enumerate() {
            let shown = text.clone();
            // Every input is parsed; one in eight also has its diagnostics
            // rendered, another one in eight a probe diagnostic. In a debug
            // build parsing costs ~1.3 µs a byte and rendering ~60 µs a
            // diagnostic: this keeps the test near 10 s.
            let show = (k + i) % 8 == 0;
            let probe = ((k + i) % 8 == 4).then(|| probe_diag(&mut rng, &text));
            let result = std::panic::catch_unwind(|| {
                if let Some(probe) = &probe {
                    let file = SourceFile::new("probe.il", text.clone());
                    let j = to_json(&file, probe); // renders too
                    assert!(j.contains(r#""rendered":"error[IL0000]: probe"#), "{j}");
                    let _ = render_short(&file, probe);
                }
                exercise_with("fuzz.il", text, show)
            });
            match result {
                Ok((_, diags)) => with_diags += usize::from(!diags.is_empty()),
                Err(_) => panic!("panic on input #{i}/{k}:\n{shown:?}"),
            }
            count += 1;
        }
    }
    // Every corpus file and built-in program as is, too.
    for src in &sources {
        exercise("corpus.il", src.to_string());
        count += 1;
    }
    println!(
        "front end robustness: {count} inputs, {with_diags} with diagnostics, in {:.1?}",
        start.elapsed()
    );
    assert!(count >= 100_000);
}

/// Number of statements (labels and instructions) in every POU.
fn stmt_count(unit: &CompilationUnit) -> usize {
    unit.items
        .iter()
        .map(|it| {
            if let Item::Pou(p) = it {
                p.body.len()
            } else {
                0
            }
        })
        .sum()
}

#[test]
fn cost_is_linear_in_the_input() {
    // Not a timed test: the sizes of what comes out must scale exactly.
    for prog in VALID {
        let (u1, d1) = exercise("x1.il", prog.to_string());
        let (u16, d16) = exercise("x16.il", prog.repeat(16));
        assert!(d1.is_empty(), "built-in program has diagnostics: {d1:?}");
        assert!(d16.is_empty());
        assert!(stmt_count(&u1) > 0);
        assert_eq!(u16.items.len(), 16 * u1.items.len());
        assert_eq!(stmt_count(&u16), 16 * stmt_count(&u1));
    }
    // Errors too: one broken POU per copy, each reported once.
    let broken = "PROGRAM p\n    LD\n    ST x\nEND_PROGRAM\n";
    let (_, d1) = exercise("b1.il", broken.to_string());
    let (_, d16) = exercise("b16.il", broken.repeat(16));
    assert!(!d1.is_empty());
    assert_eq!(d16.len(), 16 * d1.len(), "{d16:?}");
}

#[test]
fn deep_nesting_does_not_overflow_the_stack() {
    const N: usize = 100_000;
    let mut s = String::from("PROGRAM p\nVAR a : BOOL; END_VAR\n    LD a\n");
    for _ in 0..N {
        s.push_str("    AND( a\n");
    }
    for _ in 0..N {
        s.push_str("    )\n");
    }
    s.push_str("    ST a\nEND_PROGRAM\n");
    let (unit, diags) = exercise("deep.il", s.clone());
    drop(unit); // dropping a deep tree must not overflow either
    drop(diags);
    // Never closed.
    let open = s.replace("    )\n", "");
    let _ = exercise("deep_open.il", open);
    // Parentheses only, on one line, and comment openers.
    let _ = exercise(
        "parens.il",
        format!("PROGRAM p\n    LD {}\nEND_PROGRAM\n", "(".repeat(N)),
    );
    let _ = exercise("comments.il", "(*".repeat(N));
    let _ = exercise("closers.il", ")\n".repeat(N));
}

/// A column at the very end of a text whose length is a whole number of the
/// line table's 256-byte blocks (the fuzzer's 4096-byte inputs): it once
/// subtracted with overflow (found by `drive pipeline`, seed 61).
#[test]
fn column_at_the_end_of_whole_blocks() {
    for len in [256usize, 512, 4096] {
        for tail in ["", "\n", "é"] {
            let mut text = "x".repeat(len - tail.len() - 3);
            text.push_str("\nab");
            text.push_str(tail);
            assert_eq!(text.len(), len);
            let f = il_codegen::diag::SourceFile::new("t.il", text.clone());
            let (line, col) = f.line_col(len as u32);
            let last_line = text.rsplit('\n').next().unwrap();
            assert_eq!(line, text.matches('\n').count() + 1, "{len} {tail:?}");
            assert_eq!(col, last_line.chars().count() + 1, "{len} {tail:?}");
        }
    }
}

/// Line and column at every character boundary, against counting from the
/// start of the text: newlines on both sides of the 256-byte block borders,
/// multi-byte characters across them, CRLF, an empty text, a text ending in
/// a newline.
#[test]
fn line_col_agrees_with_counting_from_the_start() {
    let mut texts = vec![String::new(), "\n".into(), "\n\n".into(), "a\r\nb".into()];
    for at in [254usize, 255, 256, 257, 511, 512] {
        let mut t = "x".repeat(at);
        t.push('\n');
        t.push_str("é€\n\nyz");
        texts.push(t.clone());
        t.push('\n');
        texts.push(t);
        let mut m = "é".repeat(at / 2);
        m.push('\n');
        m.push_str(&"x".repeat(300));
        texts.push(m);
    }
    for text in texts {
        let f = il_codegen::diag::SourceFile::new("t.il", text.clone());
        for (off, _) in text.char_indices().chain([(text.len(), ' ')]) {
            let before = &text[..off];
            let line = before.matches('\n').count() + 1;
            let col = before.rsplit('\n').next().unwrap().chars().count() + 1;
            assert_eq!(f.line_col(off as u32), (line, col), "{off} in {text:?}");
            assert_eq!(f.line_of(off as u32), line, "{off} in {text:?}");
            // Any guess of the nearby line gives the same answer.
            for near in [
                0,
                1,
                line.saturating_sub(1),
                line,
                line + 1,
                line + 2,
                usize::MAX,
            ] {
                let at = format!("{off} near {near} in {text:?}");
                assert_eq!(f.line_col_near(off as u32, near), (line, col), "{at}");
                assert_eq!(f.line_of_near(off as u32, near), line, "{at}");
            }
        }
    }
}
