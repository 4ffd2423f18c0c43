//! The fuzz targets as plain functions, shared by the cargo-fuzz/libFuzzer
//! binaries (`fuzz_targets/*.rs`) and the replay test that CI runs
//! (`tests/tests/fuzz_replay.rs`, which includes this file with `#[path]`).
//!
//! Each target takes arbitrary bytes and panics only on a bug: a panic inside
//! the compiler, or a broken invariant asserted here.

use il_codegen::diag::{SourceFile, has_errors, render, render_short, to_json};

/// A fuzz target: arbitrary bytes in, a panic on a bug.
pub type Target = fn(&[u8]);

/// Every target, by name.
pub const TARGETS: &[(&str, Target)] = &[
    ("front_end", front_end),
    ("check", check),
    ("pipeline", pipeline),
];

/// How one run of a target ended when run under a time and memory budget.
#[derive(Debug, PartialEq)]
pub enum Outcome {
    /// Returned within the budgets.
    Ok,
    /// Panicked: a bug (the panic message is printed by the panic hook).
    Panicked,
    /// Still running when the budget ran out: a hang or a superlinear path,
    /// which in a compiler that runs inside users' builds is a bug too.
    TooSlow,
    /// Returned, but its peak allocation was over [`memory_budget`]: memory
    /// that grows faster than the input is a bug for the same reason.
    TooBig {
        /// Peak bytes allocated (live at once) during the run.
        peak: usize,
        /// The budget for this input.
        budget: usize,
    },
}

/// The time budget of one run: `IL_FUZZ_BUDGET_SECS`, or `default_secs`.
pub fn budget(default_secs: u64) -> std::time::Duration {
    std::time::Duration::from_secs(
        std::env::var("IL_FUZZ_BUDGET_SECS")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(default_secs),
    )
}

/// The memory budget of one run on an input of `len` bytes: the larger of a
/// floor (`IL_FUZZ_MEM_MIB`, default 128 MiB: the fixed cost of the pipeline
/// on small inputs, a few MiB, with a wide margin) and 2000 times the input
/// (linear memory with a generous constant: the checked IR, the emitted
/// tokens and the formatted text of a 4 KiB input stay far below it).
pub fn memory_budget(len: usize) -> usize {
    let floor_mib: usize = std::env::var("IL_FUZZ_MEM_MIB")
        .ok()
        .and_then(|s| s.parse().ok())
        // 64 MiB until the merges of the LSP's CR record and `visit`:
        // tests/plc/deep_nesting.il then peaked at 78 MB in `pipeline`.
        .unwrap_or(128);
    (floor_mib << 20).max(len.saturating_mul(2000))
}

/// A global allocator that counts the bytes live on each thread and their
/// peak (thread-local, so runs on other threads do not mix in). Install it
/// with `#[global_allocator]` in a binary (the drive, the libFuzzer targets,
/// the replay test); without it every peak reads 0 and no memory budget
/// applies.
pub struct Counting;

thread_local! {
    static LIVE: std::cell::Cell<isize> = const { std::cell::Cell::new(0) };
    static PEAK: std::cell::Cell<isize> = const { std::cell::Cell::new(0) };
}

fn note(delta: isize) {
    // `try_with`: an allocation during thread teardown is not counted.
    let _ = LIVE.try_with(|l| {
        let now = l.get() + delta;
        l.set(now);
        let _ = PEAK.try_with(|p| p.set(p.get().max(now)));
    });
}

// SAFETY: every call is forwarded unchanged to the system allocator; the
// counting touches only const-initialised thread-locals without destructors
// (no allocation, no unwinding).
unsafe impl std::alloc::GlobalAlloc for Counting {
    unsafe fn alloc(&self, l: std::alloc::Layout) -> *mut u8 {
        note(l.size() as isize);
        unsafe { std::alloc::System.alloc(l) }
    }
    unsafe fn alloc_zeroed(&self, l: std::alloc::Layout) -> *mut u8 {
        note(l.size() as isize);
        unsafe { std::alloc::System.alloc_zeroed(l) }
    }
    unsafe fn dealloc(&self, p: *mut u8, l: std::alloc::Layout) {
        note(-(l.size() as isize));
        unsafe { std::alloc::System.dealloc(p, l) }
    }
    unsafe fn realloc(&self, p: *mut u8, l: std::alloc::Layout, new: usize) -> *mut u8 {
        note(new as isize - l.size() as isize);
        unsafe { std::alloc::System.realloc(p, l, new) }
    }
}

/// Run `target` on `data` on this thread and return its peak allocation
/// (bytes live at once above what was live before; 0 without [`Counting`]).
pub fn peak_of(target: Target, data: &[u8]) -> usize {
    let base = LIVE.with(|l| l.get());
    PEAK.with(|p| p.set(base));
    target(data);
    (PEAK.with(|p| p.get()) - base).max(0) as usize
}

/// For the libFuzzer binaries: run `target` and panic (a finding libFuzzer
/// saves) when its peak allocation is over [`memory_budget`].
pub fn within_memory(target: Target, data: &[u8]) {
    let peak = peak_of(target, data);
    let budget = memory_budget(data.len());
    assert!(
        peak <= budget,
        "memory budget exceeded: peak {peak} bytes for an input of {} bytes (budget {budget})",
        data.len()
    );
}

/// Run `target` on `data` in a thread of its own and wait at most `budget`;
/// the peak allocation is checked against [`memory_budget`].
/// A run over budget is reported, not waited for: its thread is left behind
/// (the caller stops soon after with the input saved).
pub fn run_within(target: Target, data: Vec<u8>, budget: std::time::Duration) -> Outcome {
    run_measured(target, data, budget).0
}

/// [`run_within`], with the run's peak allocation in bytes.
pub fn run_measured(
    target: Target,
    data: Vec<u8>,
    budget: std::time::Duration,
) -> (Outcome, usize) {
    let mem_budget = memory_budget(data.len());
    let (tx, rx) = std::sync::mpsc::channel();
    let spawned = std::thread::Builder::new()
        .name("fuzz-run".into())
        .spawn(move || {
            let r = std::panic::catch_unwind(|| peak_of(target, &data));
            let _ = tx.send(r.ok());
        });
    if spawned.is_err() {
        return (Outcome::Panicked, 0);
    }
    match rx.recv_timeout(budget) {
        Ok(Some(peak)) if peak > mem_budget => (
            Outcome::TooBig {
                peak,
                budget: mem_budget,
            },
            peak,
        ),
        Ok(Some(peak)) => (Outcome::Ok, peak),
        Ok(None) | Err(std::sync::mpsc::RecvTimeoutError::Disconnected) => (Outcome::Panicked, 0),
        Err(std::sync::mpsc::RecvTimeoutError::Timeout) => (Outcome::TooSlow, 0),
    }
}

/// Sources are text: the CLI refuses non-UTF-8 files before parsing, so feed
/// the lossy decoding, which still holds every odd character.
fn source(data: &[u8]) -> SourceFile {
    SourceFile::new("fuzz.il", String::from_utf8_lossy(data).into_owned())
}

/// Render the first diagnostics through every renderer. Rendering dominates
/// the cost: the first ones are enough to reach every rendering path.
fn render_all(file: &SourceFile, diags: &[il_codegen::diag::Diagnostic]) {
    // Every diagnostic through the terminal renderer (a file has at most
    // about 200, `diag::limit`): many reports on one long line were once
    // quadratic there.
    let _ = render(file, diags, false);
    let shown = &diags[..diags.len().min(16)];
    let _ = render(file, shown, true);
    for d in shown {
        let _ = render_short(file, d);
        let j = to_json(file, d);
        assert!(!j.contains('\n'), "JSON diagnostic spans lines: {j}");
    }
}

/// The parser and every diagnostic renderer.
pub fn front_end(data: &[u8]) {
    let file = source(data);
    let (_unit, diags) = il_codegen::ast::parse(&file);
    render_all(&file, &diags);
}

/// Parser and checker (`Program::check`, what `ilc check` runs). Checking
/// is deterministic: the same file checked again, and checked beside an
/// empty second file, gives the same diagnostics (a "did you mean" that
/// depended on hash-map order once differed).
pub fn check(data: &[u8]) {
    let file = source(data);
    let checked = il_codegen::Program::new().il(file.clone()).check();
    let diags = &checked.diagnostics()[0];
    render_all(&file, diags);
    let again = il_codegen::Program::new()
        .il(file.clone())
        .il(SourceFile::new("empty.il", ""))
        .check()
        .into_diagnostics();
    assert_eq!(again.len(), 2, "one list per input");
    assert!(&again[0] == diags, "checking is not deterministic");
    assert!(again[1].is_empty(), "an empty file has no diagnostics");
}

/// The whole pipeline: parse, check, emit, format. The emitted Rust must
/// parse, contain no `unsafe` and no item that is not generated for a POU or
/// type, and code is emitted exactly when the check found no error.
pub fn pipeline(data: &[u8]) {
    let file = source(data);
    macro_expansion(&file.text);
    let program = il_codegen::Program::new().il(file.clone());
    let checked = program.check();
    let diags = &checked.diagnostics()[0];
    let compiled = checked.emit(il_codegen::EmitOptions {
        line_markers: true,
        ..Default::default()
    });
    let Some(mut compiled) = compiled else {
        assert!(has_errors(diags), "nothing emitted without an error");
        return;
    };
    assert!(!has_errors(diags), "code emitted despite errors");
    let c = compiled.remove(0);
    assert!(!has_errors(&c.warnings), "compile succeeded with an error");
    // The emitter writes text; `il!` parses it into tokens once.
    let ts: proc_macro2::TokenStream = c
        .text
        .parse()
        .unwrap_or_else(|e| panic!("emitted text does not lex: {e}\n{}", c.text));
    let tokens = syn::parse2::<syn::File>(ts.clone())
        .unwrap_or_else(|e| panic!("emitted text does not parse: {e}\n{}", c.text));
    assert_items(&tokens, &c.pous);
    assert_no_unsafe(ts.clone());
    // The file writer: formatted, with `// N: <IL line>` comments.
    let text = c.file_text();
    let parsed = syn::parse_file(&text)
        .unwrap_or_else(|e| panic!("the written file does not parse: {e}\n{text}"));
    // The comments must not have changed the code: the file holds exactly
    // the emitted tokens less the line markers (which became comments), as
    // the formatter prints them.
    let emitted = syn::parse2::<syn::File>(strip_markers(ts))
        .unwrap_or_else(|e| panic!("emitted tokens without markers do not parse: {e}"));
    assert!(
        prettyplease::unparse(&parsed) == prettyplease::unparse(&emitted),
        "the written file is not the emitted code:\n{text}"
    );
    // rustc refuses bidirectional text controls even in comments
    // (`text_direction_codepoint_in_comment`, deny by default).
    assert!(
        !text
            .chars()
            .any(|c| matches!(c, '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}')),
        "the written file holds a bidirectional control:\n{text}"
    );
    for line in text.lines() {
        let t = line.trim_start();
        assert!(
            !t.starts_with("__il_line!"),
            "a line marker was left in the file: {line}"
        );
    }
}

/// `il!(r#"..."#)`: the generated items, or `compile_error!`s and stubs of
/// the POUs. Either way the expansion parses as items, and it is never the
/// message of a caught compiler panic.
fn macro_expansion(text: &str) {
    let out = il_codegen::expand::expand(&[il_codegen::expand::Tok::string(text, 0)]);
    for (msg, _) in &out.errors {
        assert!(
            !msg.contains("internal error in the IL compiler"),
            "il! caught a compiler panic: {msg}"
        );
    }
    syn::parse_file(&out.code).unwrap_or_else(|e| panic!("il! expansion does not parse: {e}"));
}

/// The tokens without the `__il_line!(N);` markers.
fn strip_markers(ts: proc_macro2::TokenStream) -> proc_macro2::TokenStream {
    use proc_macro2::TokenTree;
    let tts: Vec<TokenTree> = ts.into_iter().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < tts.len() {
        if matches!(&tts[i], TokenTree::Ident(id) if id == "__il_line") {
            i += 4; // `__il_line` `!` `(N)` `;`
            continue;
        }
        out.push(match &tts[i] {
            TokenTree::Group(g) => {
                let mut ng = proc_macro2::Group::new(g.delimiter(), strip_markers(g.stream()));
                ng.set_span(g.span());
                TokenTree::Group(ng)
            }
            t => t.clone(),
        });
        i += 1;
    }
    out.into_iter().collect()
}

/// Every top-level item is a struct, enum, fn or impl (or the `const _`
/// signature check of a host function), and every struct,
/// enum and fn is named after a POU or a user type (the POU list does not
/// hold types, so only count them).
fn assert_items(f: &syn::File, pous: &[String]) {
    let mut named = 0;
    for item in &f.items {
        match item {
            syn::Item::Struct(_) | syn::Item::Enum(_) | syn::Item::Fn(_) => named += 1,
            // A host FUNCTION (`{extern}`): the check of the crate's function.
            syn::Item::Const(c) if c.ident == "_" => named += 1,
            syn::Item::Impl(_) => {}
            other => panic!("unexpected top-level item: {}", quote_item(other)),
        }
    }
    assert!(
        named >= pous.len(),
        "{named} named items for {} POUs",
        pous.len()
    );
}

fn quote_item(i: &syn::Item) -> String {
    use quote::ToTokens;
    i.to_token_stream().to_string()
}

/// Generated code never contains `unsafe` (a raw `r#unsafe` is a name).
fn assert_no_unsafe(ts: proc_macro2::TokenStream) {
    for tt in ts {
        match tt {
            proc_macro2::TokenTree::Ident(i) => {
                assert!(i != "unsafe", "emitted code contains `unsafe`")
            }
            proc_macro2::TokenTree::Group(g) => assert_no_unsafe(g.stream()),
            _ => {}
        }
    }
}
