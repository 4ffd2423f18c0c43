//! `Session`: a program checked again after each edit gives what a check
//! from scratch of the same text gives (diagnostics, trees, resolutions,
//! IR, the rendered messages with their lines and columns), over seeded
//! random edit sequences: inserts and deletions inside POUs, across their
//! boundaries, in declarations, lines added and removed, breaking and
//! fixing the syntax.

use il_codegen::{Program, Session, SourceFile};

/// xorshift64*: the sequences are the same on every run.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

const BASE: &str = "TYPE
    Mode : (Idle, Run, Stop);
    Pair : STRUCT a : INT; b : BOOL; END_STRUCT;
END_TYPE

FUNCTION Twice : INT
VAR_INPUT v : INT; END_VAR
    LD   v
    MUL  2
    ST   Twice
END_FUNCTION

FUNCTION_BLOCK Counter
VAR_INPUT up : BOOL; END_VAR
VAR_OUTPUT n : INT; END_VAR
VAR edge : R_TRIG; m : Mode; p : Pair; END_VAR
    CAL  edge(CLK := up)
    LD   edge.Q
    JMPCN done
    LD   n
    ADD  1
    ST   n
    LD   n
    Twice
    ST   p.a
done:
    LD   Mode#Run
    ST   m
END_FUNCTION_BLOCK

(* a comment between items (* with an inner open *)

FUNCTION_BLOCK Blink
VAR_INPUT en : BOOL; END_VAR
VAR_OUTPUT q : BOOL; END_VAR
VAR t : TON; c : Counter; END_VAR
    LD   en
    ANDN q
    ST   t.IN
    CAL  t(PT := T#500ms)
    LD   t.Q
    ST   q
    CAL  c(up := q)
END_FUNCTION_BLOCK

PROGRAM Main
VAR b : Blink; x : INT; END_VAR
    CAL  b(en := TRUE)
    LD   b.q
    SEL  0, 1
    ST   x
END_PROGRAM

CONFIGURATION Plc
    RESOURCE Cpu ON Any
        TASK Fast(INTERVAL := T#10ms, PRIORITY := 1);
        PROGRAM Inst WITH Fast : Main;
    END_RESOURCE
END_CONFIGURATION
";

/// What an editor's user types or deletes.
const PIECES: &[&str] = &[
    "    LD   x\n",
    "    ADD  nosuch\n",
    "nosuch",
    "    ST   q\n",
    "END_FUNCTION_BLOCK\n",
    "FUNCTION_BLOCK Extra\nVAR_INPUT i : INT; END_VAR\n    LD i\nEND_FUNCTION_BLOCK\n",
    "VAR_INPUT z : INT; END_VAR\n",
    "(*",
    "*)",
    "(* note *)\n",
    "{extern}\n",
    "'",
    ";",
    " ",
    "\n",
    "\r\n",
    "  \n",
    "x",
    ":",
    "INT",
    "BOOL",
    "    JMP  done\n",
    "lbl:\n",
    "Ä",
];

/// A position in `text` on a character boundary, often at a line start.
fn position(rng: &mut Rng, text: &str) -> usize {
    let mut at = rng.below(text.len() + 1);
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    if rng.below(3) == 0 {
        at = text[..at].rfind('\n').map_or(0, |i| i + 1);
    }
    at
}

fn edit(rng: &mut Rng, text: &str, history: &[String]) -> String {
    let mut t = text.to_string();
    match rng.below(14) {
        0..=3 => {
            let at = position(rng, &t);
            t.insert_str(at, PIECES[rng.below(PIECES.len())]);
        }
        4..=6 => {
            let lo = position(rng, &t);
            let most = if rng.below(4) == 0 { 400 } else { 30 };
            let mut hi = (lo + 1 + rng.below(most)).min(t.len());
            while !t.is_char_boundary(hi) {
                hi += 1;
            }
            t.replace_range(lo..hi, "");
        }
        7..=9 => {
            // An operand renamed: a semantic error, not a syntax one.
            let at = position(rng, &t);
            if let Some(i) = t[at..].find("    LD   ") {
                t.insert_str(at + i + 9, "un");
            }
        }
        10 => {
            // Duplicate a line.
            let at = position(rng, &t);
            let end = t[at..].find('\n').map_or(t.len(), |i| at + i + 1);
            let line = t[at..end].to_string();
            t.insert_str(at, &line);
        }
        // Undo to an earlier text (often the first, clean one): errors fixed again.
        _ if rng.below(2) == 0 => return history[0].clone(),
        _ => return history[rng.below(history.len())].clone(),
    }
    t
}

fn program(names: &[&str], texts: &[String]) -> Program {
    names.iter().zip(texts).fold(
        Program::new().cr_steps(true).resolutions(true),
        |p, (name, text)| p.source(SourceFile::new(*name, text.clone())),
    )
}

/// Check `files` through the session and from scratch; they must agree.
/// Returns how many files the session parsed only in part, and how many
/// POUs it checked (the others' results reused).
fn compare(session: &mut Session, names: &[&str], texts: &[String], what: &str) -> (usize, usize) {
    let fresh = program(names, texts).check();
    let again = session.check(program(names, texts));
    assert_eq!(
        again.diagnostics(),
        fresh.diagnostics(),
        "{what}: diagnostics"
    );
    assert_eq!(again.syntax(), fresh.syntax(), "{what}: syntax trees");
    assert_eq!(
        again.resolutions(),
        fresh.resolutions(),
        "{what}: resolutions"
    );
    assert_eq!(
        format!("{:?}", again.partial_ir()),
        format!("{:?}", fresh.partial_ir()),
        "{what}: IR"
    );
    // What a user reads: each message with its file, line and column.
    assert_eq!(again.render(false), fresh.render(false), "{what}: messages");
    let partial = session
        .reparsed()
        .iter()
        .zip(texts)
        .filter(|(r, text)| r.as_ref().is_some_and(|r| r.len() < text.len()))
        .count();
    (partial, session.pous_checked())
}

/// Runs `edits` random edits; returns how many times the session parsed a
/// file in part, checked one POU alone, and checked one POU alone after an
/// edit that added or removed lines (the POUs after it moved).
fn run(seed: u64, start: &[(&str, String)], edits: usize) -> (usize, usize, usize) {
    let mut rng = Rng(seed);
    let mut texts: Vec<String> = start.iter().map(|(_, t)| t.clone()).collect();
    let names: Vec<&str> = start.iter().map(|(n, _)| *n).collect();
    let mut history = vec![texts.clone()];
    let mut session = Session::new();
    compare(&mut session, &names, &texts, "the first check");
    let (mut partial, mut fast, mut some) = (0, 0, 0);
    for step in 0..edits {
        if rng.below(6) == 0 {
            // Every file back to its first text (a program without errors).
            texts = history[0].clone();
        }
        let k = rng.below(texts.len());
        let earlier: Vec<String> = history.iter().map(|h| h[k].clone()).collect();
        let lines = |t: &str| t.matches('\n').count();
        let before = texts.iter().map(|t| lines(t)).sum::<usize>();
        texts[k] = edit(&mut rng, &texts[k], &earlier);
        let moved = texts.iter().map(|t| lines(t)).sum::<usize>() != before;
        history.push(texts.clone());
        let what = format!("seed {seed}, edit {step} of file {}", names[k]);
        let (p, f) = compare(&mut session, &names, &texts, &what);
        partial += p;
        fast += usize::from(f == 1);
        some += usize::from(f == 1 && moved);
    }
    (partial, fast, some)
}

#[test]
fn random_edits_check_as_a_fresh_check_does() {
    let clean = program(&["plc/main.il"], &[BASE.to_string()]).check();
    assert_eq!(clean.diagnostics()[0], [], "the starting text is clean");
    let (mut partial, mut fast, mut some) = (0, 0, 0);
    let total = 12 * 60;
    for seed in 1..=12u64 {
        let (p, f, s) = run(
            seed.wrapping_mul(0x9E37_79B9_7F4A_7C15),
            &[("plc/main.il", BASE.to_string())],
            60,
        );
        partial += p;
        fast += f;
        some += s;
    }
    // The short ways are taken often (most random edits break the syntax,
    // and the edit after a syntax error parses the file whole), or the test
    // would prove nothing.
    assert!(
        partial * 10 > total,
        "parsed in part {partial} of {total} times"
    );
    assert!(fast * 60 > total, "one POU checked {fast} of {total} times");
    assert!(some > 5, "one POU checked after lines moved {some} times");
}

#[test]
fn random_edits_in_a_program_of_two_files() {
    let (types, rest) = BASE.split_at(BASE.find("FUNCTION Twice").unwrap());
    let (mut partial, mut fast) = (0, 0);
    for seed in 100..106 {
        let (p, f, _) = run(
            seed,
            &[
                ("plc/types.il", types.to_string()),
                ("plc/pous.il", rest.to_string()),
            ],
            50,
        );
        partial += p;
        fast += f;
    }
    assert!(partial > 20, "parsed in part {partial} times");
    assert!(fast >= 5, "one POU checked {fast} times");
}

/// The IL files of the corpus (real programs, vendor forms), edited.
#[test]
fn random_edits_of_corpus_files() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/corpus");
    let Ok(entries) = std::fs::read_dir(&dir) else {
        eprintln!("skipped: no corpus at {}", dir.display());
        return;
    };
    let mut paths: Vec<_> = entries
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "il"))
        .collect();
    paths.sort();
    let mut partial = 0;
    for (i, p) in paths.iter().enumerate() {
        let Ok(text) = std::fs::read_to_string(p) else {
            continue;
        };
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        partial += run(i as u64 + 7, &[(&name, text)], 12).0;
    }
    assert!(paths.is_empty() || partial > 0, "never parsed in part");
}

/// An edit inside one POU of a large file parses that POU alone.
#[test]
fn an_edit_inside_a_pou_parses_that_pou_only() {
    let fb = |i: usize| {
        format!(
            "FUNCTION_BLOCK Fb{i}\nVAR_INPUT a : BOOL; END_VAR\nVAR_OUTPUT q : BOOL; END_VAR\n    LD a\n    ST q\nEND_FUNCTION_BLOCK\n"
        )
    };
    let text: String = (0..50).map(fb).collect();
    let mut session = Session::new();
    let big = ["big.il"];
    compare(&mut session, &big, std::slice::from_ref(&text), "open");
    let at = text.find("FUNCTION_BLOCK Fb20\n").unwrap();
    let edited = text.replacen("    LD a\n", "    LD nosuch\n", 21);
    // Only the 21st replacement differs from `text` with 20 replaced.
    let base = text.replacen("    LD a\n", "    LD nosuch\n", 20);
    compare(&mut session, &big, &[base], "twenty edits at once");
    compare(
        &mut session,
        &big,
        std::slice::from_ref(&edited),
        "one edit",
    );
    assert_eq!(
        session.pous_checked(),
        1,
        "the other POUs' results are reused"
    );
    let len = fb(20).len() + "nosuch".len() - 1;
    let at = at + 20 * ("nosuch".len() - 1);
    assert_eq!(session.reparsed(), [Some(at..at + len)]);
    // A line added: the POUs after the edited one are moved, not checked.
    let fb20 = edited.find("FUNCTION_BLOCK Fb20\n").unwrap();
    let mut longer = edited.clone();
    longer.insert_str(
        fb20 + edited[fb20..].find("    ST q\n").unwrap(),
        "    ST q\n",
    );
    compare(
        &mut session,
        &big,
        std::slice::from_ref(&longer),
        "a new line",
    );
    assert_eq!(session.pous_checked(), 1, "FB20 alone");
    compare(
        &mut session,
        &big,
        std::slice::from_ref(&edited),
        "the line removed",
    );
    assert_eq!(session.pous_checked(), 1);
    // The same text again: nothing is checked again.
    compare(&mut session, &big, &[edited], "no edit");
    assert_eq!(session.pous_checked(), 0);
}
