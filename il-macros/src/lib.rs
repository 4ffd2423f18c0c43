//! `il!`: IEC 61131-3 Instruction List (IL) inside Rust source, compiled
//! to Rust items where the macro stands.
//!
//! ```
//! il_macros::il!(r#"
//! FUNCTION_BLOCK Motor
//!   VAR_INPUT start, stop : BOOL; END_VAR
//!   VAR_OUTPUT run : BOOL; END_VAR
//!   LD start
//!   OR run
//!   ANDN stop
//!   ST run
//! END_FUNCTION_BLOCK
//! "#);
//!
//! let mut ctx = il_std::Cycle::new();
//! let mut m = Motor::default();
//! m.start = true;
//! m.call(&mut ctx);
//! assert!(m.run);
//! ```
//!
//! # Forms
//! - `il!(r#"...IL..."#)`: inline IL, in a raw string (IL's `T#1s` and
//!   `'text'` are not Rust tokens).
//! - `il!(file = "plc/motor.il")`: a file relative to the crate root
//!   (`CARGO_MANIFEST_DIR`); edits to it rebuild the crate. A file whose
//!   text starts with `<` (or named `.xml`) is a PLCopen TC6 XML project,
//!   whatever its name: that needs the `plcopen` feature, off by
//!   default so that crates reading only IL compile no XML parser
//!   (`il-macros = { version = "0.1", features = ["plcopen"] }`; without it
//!   the call fails with IL0210, which says so). A CODESYS V2.3 export
//!   (`.exp`) needs the `exp` feature the same way (IL0410 without it).
//! - `il!(files = ["plc/types.il", "plc/tank.il"])`: several files as one
//!   program.
//!
//! # Options
//! - `, serde` after the input derives `serde::Serialize` and `Deserialize`
//!   on the generated types (the crate depends on `serde` and enables
//!   `il-std`'s `serde` feature).
//! - `, dialect = "m221"`: the text is a Modicon M221 / TwidoSuite
//!   Instruction List listing (`LD %I0.1`, `BLK %TM0`, `SR1:` ...,
//!   timers configured in `(*@ %TM0 TON BASE=100ms PRESET=50 *)`
//!   comments), translated to IEC IL; it needs the `plcopen` feature,
//!   which holds the M221 translation (IL0210 without it).
//! - `, encoding = "windows-1251"`: the encoding of the files that are not
//!   UTF-8 (a WHATWG label: `windows-1252`, `windows-1250`, `iso-8859-15`
//!   ...), as PLC IDEs on Windows export them. Without it such a file is
//!   read as Windows-1252 (the warning the other front ends show, IL0039,
//!   is not shown here). An unknown label is an error at it. Code pages
//!   need the `encodings` feature (`features = ["encodings"]`), off by
//!   default because its tables are about 1.7 s of a cold build: without
//!   it a file must be UTF-8 or UTF-16 (with or without a byte order mark),
//!   and one that is not fails with IL0040, which names the feature.
//!
//! # One program per call
//! Each `il!` is a program of its own: its POUs see the TYPEs and
//! FUNCTION_BLOCKs of that call only. A PROGRAM that uses a TYPE or FB
//! declared in another file must be compiled with it: list both in one
//! `il!(files = [...])`, or compile them together with
//! `il_codegen::Builder` in build.rs. Two calls that declare the same TYPE
//! generate two Rust types of that name, so keep each in one call.
//!
//! # Errors
//! Each IL error becomes a `compile_error!` at the macro, whose message
//! gives the code, the Rust file, line and column of the error inside the
//! string (on the `-->` line that editors' rustc problem matchers read),
//! the source line, and the IL line and column (a proc macro cannot point
//! rustc's own arrow inside a string literal). Warnings are not shown (proc
//! macros have no stable API for them): `ilc check` and build.rs show them.
//!
//! The crate using `il!` depends on `il-std`, the runtime the generated code
//! calls.

use il_codegen::expand::{SpanId, Tok, expand};
use proc_macro::{Delimiter, Group, Ident, Literal, Punct, Spacing, Span, TokenStream, TokenTree};

/// Compile IL to Rust items at the call site.
#[proc_macro]
pub fn il(input: TokenStream) -> TokenStream {
    // The library reads the call; the spans stay here, numbered.
    let mut spans = Vec::new();
    let toks = tokens(input, &mut spans);
    let out = expand(&toks);
    let span = |id: SpanId| {
        spans
            .get(id as usize)
            .copied()
            .unwrap_or_else(Span::call_site)
    };
    let mut items: TokenStream = out.code.parse().unwrap_or_else(|e| {
        let msg =
            format!("internal error in the IL compiler: the generated Rust does not lex ({e})");
        compile_error(&msg, Span::call_site())
    });
    for (msg, at) in &out.errors {
        items.extend(compile_error(msg, span(*at)));
    }
    items
}

fn tokens(input: TokenStream, spans: &mut Vec<Span>) -> Vec<Tok> {
    fn id(spans: &mut Vec<Span>, s: Span) -> SpanId {
        spans.push(s);
        (spans.len() - 1) as SpanId
    }
    input
        .into_iter()
        .map(|t| match t {
            TokenTree::Literal(l) => Tok::Literal {
                text: l.to_string(),
                line: l.span().line(),
                column: l.span().column(),
                file: l.span().file(),
                span: id(spans, l.span()),
            },
            TokenTree::Ident(i) => Tok::Ident(i.to_string(), id(spans, i.span())),
            TokenTree::Punct(p) => Tok::Punct(p.as_char(), id(spans, p.span())),
            TokenTree::Group(g) => {
                let open = match g.delimiter() {
                    Delimiter::Bracket => '[',
                    Delimiter::Parenthesis => '(',
                    Delimiter::Brace => '{',
                    Delimiter::None => ' ',
                };
                let span = id(spans, g.span());
                Tok::Group {
                    open,
                    inner: tokens(g.stream(), spans),
                    span,
                }
            }
        })
        .collect()
}

/// `::core::compile_error!("msg");` at `span`.
fn compile_error(msg: &str, span: Span) -> TokenStream {
    let mut msg = Literal::string(msg);
    msg.set_span(span);
    let tree = |mut t: TokenTree| {
        t.set_span(span);
        t
    };
    let colons = || {
        [
            tree(Punct::new(':', Spacing::Joint).into()),
            tree(Punct::new(':', Spacing::Alone).into()),
        ]
    };
    let mut out: Vec<TokenTree> = Vec::new();
    out.extend(colons());
    out.push(Ident::new("core", span).into());
    out.extend(colons());
    out.push(Ident::new("compile_error", span).into());
    out.push(tree(Punct::new('!', Spacing::Alone).into()));
    out.push(tree(
        Group::new(Delimiter::Parenthesis, TokenTree::from(msg).into()).into(),
    ));
    out.push(tree(Punct::new(';', Spacing::Alone).into()));
    out.into_iter().collect()
}
