//! Completion, from the text before the cursor (which is often not valid IL
//! yet) and the index of the last check: operators in the operator field,
//! labels after JMP, FB instances after CAL, members after `inst.`, formal
//! parameter names inside a call's list, variables elsewhere.

use lsp_types::{CompletionItem, CompletionItemKind, Position, Uri};

use super::index::{Index, Kind, Member, SymId};
use super::workspace::Workspace;
use il_codegen::ast::{PouKind, VarKind};
use il_interp::il_std::signature as sig;

/// The IL operators (IEC 61131-3 Table 68 and the FB input operators),
/// with what each does.
pub(super) const OPERATORS: &[(&str, &str)] = &[
    ("LD", "load the operand into the CR"),
    ("LDN", "load the operand's complement"),
    ("ST", "store the CR"),
    ("STN", "store the CR's complement"),
    ("S", "set a BOOL when the CR is TRUE"),
    ("R", "reset a BOOL when the CR is TRUE"),
    ("AND", "Boolean or bitwise AND"),
    ("ANDN", "AND with the operand's complement"),
    ("OR", "Boolean or bitwise OR"),
    ("ORN", "OR with the operand's complement"),
    ("XOR", "exclusive OR"),
    ("XORN", "XOR with the operand's complement"),
    ("NOT", "complement the CR"),
    ("ADD", "addition"),
    ("SUB", "subtraction"),
    ("MUL", "multiplication"),
    ("DIV", "division"),
    ("MOD", "remainder"),
    ("GT", "CR > operand"),
    ("GE", "CR >= operand"),
    ("EQ", "CR = operand"),
    ("NE", "CR <> operand"),
    ("LE", "CR <= operand"),
    ("LT", "CR < operand"),
    ("JMP", "jump to a label"),
    ("JMPC", "jump when the CR is TRUE"),
    ("JMPCN", "jump when the CR is FALSE"),
    ("CAL", "call a function block instance"),
    ("CALC", "call when the CR is TRUE"),
    ("CALCN", "call when the CR is FALSE"),
    ("RET", "return"),
    ("RETC", "return when the CR is TRUE"),
    ("RETCN", "return when the CR is FALSE"),
    ("S1", "set input of an SR"),
    ("R1", "reset input of an RS"),
    ("CLK", "clock input of R_TRIG / F_TRIG"),
    ("CU", "count-up input of a counter"),
    ("CD", "count-down input of a counter"),
    ("PV", "preset value of a counter"),
    ("IN", "input of a timer"),
    ("PT", "preset time of a timer"),
];

/// Operators a `(` defers rather than calls.
const DEFERRABLE: &[&str] = &[
    "AND", "ANDN", "&", "&N", "OR", "ORN", "XOR", "XORN", "ADD", "SUB", "MUL", "DIV", "MOD", "GT",
    "GE", "EQ", "NE", "LE", "LT",
];

/// How far back a call's open `(` is looked for.
const CALL_LOOKBACK: usize = 4096;

pub fn complete(ws: &Workspace, uri: &Uri, pos: Position) -> Vec<CompletionItem> {
    let Some((k, off)) = ws.locate(uri, pos) else {
        return Vec::new();
    };
    let text = &ws.docs[k].text;
    let lines = &ws.analysis.lines[k];
    let (lo, _) = lines.line_range(text, lines.line_of(off));
    let prefix = text.get(lo..off).unwrap_or("");
    if prefix.contains("(*") && !prefix.contains("*)") {
        return Vec::new(); // in a comment
    }
    let Some(ix) = ws.analysis.index(k) else {
        return Vec::new();
    };
    let pou = ix.pou_at(k, off);
    if let Some(items) = call_params(ix, pou, text, off) {
        return items;
    }
    let code = strip_label(prefix.trim_start());
    if !code.contains(char::is_whitespace) {
        return operators(ix);
    }
    let Some(pou) = pou else {
        return Vec::new();
    };
    let op = code
        .split_whitespace()
        .next()
        .unwrap_or("")
        .to_ascii_uppercase();
    let word = code
        .rsplit(|c: char| c.is_whitespace() || c == '(' || c == ',')
        .next()
        .unwrap_or("");
    if let Some((chain, _)) = word.rsplit_once('.') {
        return members(ix, pou, chain);
    }
    match op.as_str() {
        "JMP" | "JMPC" | "JMPCN" => ix
            .pou_labels
            .get(&pou)
            .into_iter()
            .flatten()
            .map(|&l| item(&ix.symbols[l].name, CompletionItemKind::REFERENCE, "label"))
            .collect(),
        "CAL" | "CALC" | "CALCN" => vars(ix, pou)
            .filter(|&v| is_instance(ix, v))
            .map(|v| var_item(ix, v))
            .collect(),
        _ => vars(ix, pou).map(|v| var_item(ix, v)).collect(),
    }
}

/// `lbl: LD x` → `LD x` (not `x := 1`).
fn strip_label(code: &str) -> &str {
    let end = code
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(code.len());
    let rest = &code[end..];
    match rest.trim_start().strip_prefix(':') {
        Some(r) if end > 0 && !r.starts_with('=') => r.trim_start(),
        _ => code,
    }
}

fn item(label: &str, kind: CompletionItemKind, detail: &str) -> CompletionItem {
    CompletionItem {
        label: label.to_string(),
        kind: Some(kind),
        detail: (!detail.is_empty()).then(|| detail.to_string()),
        ..Default::default()
    }
}

fn operators(ix: &Index) -> Vec<CompletionItem> {
    let mut out: Vec<CompletionItem> = OPERATORS
        .iter()
        .map(|(n, d)| item(n, CompletionItemKind::OPERATOR, d))
        .collect();
    for (name, &p) in &ix.pou_by_name {
        let s = &ix.symbols[p];
        if s.kind == Kind::Pou(PouKind::Function) && !name.is_empty() {
            out.push(item(&s.name, CompletionItemKind::FUNCTION, &s.decl));
        }
    }
    out.extend(
        sig::SIGNATURES
            .iter()
            .map(|f| item(f.name, CompletionItemKind::FUNCTION, f.doc)),
    );
    out
}

fn vars(ix: &Index, pou: SymId) -> impl Iterator<Item = SymId> + '_ {
    ix.members.get(&pou).into_iter().flatten().copied()
}

fn var_item(ix: &Index, v: SymId) -> CompletionItem {
    let s = &ix.symbols[v];
    let detail = s.decl.lines().nth(1).unwrap_or("").trim().to_string();
    item(&s.name, CompletionItemKind::VARIABLE, &detail)
}

/// An instance of a user or standard function block (or an array of them).
fn is_instance(ix: &Index, v: SymId) -> bool {
    ix.symbols[v].ty.as_deref().is_some_and(|t| {
        ix.pou_by_name
            .get(t)
            .is_some_and(|&p| ix.symbols[p].kind == Kind::Pou(PouKind::FunctionBlock))
            || sig::lookup_fb(t).is_some()
    })
}

/// The type (upper case) of `a.b[1].c`, from POU `pou`'s variables.
fn chain_type(ix: &Index, pou: SymId, chain: &str) -> Option<String> {
    let mut parts = chain
        .split('.')
        .map(|p| p.split('[').next().unwrap_or("").trim());
    let first = ix.var_in(pou, parts.next()?)?;
    let mut ty = ix.symbols[first].ty.clone();
    for p in parts {
        ty = match ix.member(ty.as_deref()?, p)? {
            Member::Sym(m) => ix.symbols[m].ty.clone(),
            _ => None,
        };
    }
    ty
}

fn members(ix: &Index, pou: SymId, chain: &str) -> Vec<CompletionItem> {
    let Some(ty) = chain_type(ix, pou, chain) else {
        return Vec::new();
    };
    type_members(ix, &ty, false)
}

/// The members of type `ty` seen from outside: an FB's inputs, outputs and
/// in-outs, a STRUCT's fields; with `formal`, as `name := ` / `name => `.
fn type_members(ix: &Index, ty: &str, formal: bool) -> Vec<CompletionItem> {
    let param = |name: &str, output: bool, detail: String| {
        let mut it = item(name, CompletionItemKind::FIELD, &detail);
        if formal {
            it.kind = Some(CompletionItemKind::PROPERTY);
            it.insert_text = Some(format!("{name} {} ", if output { "=>" } else { ":=" }));
        }
        it
    };
    if let Some(t) = ix.type_sym(ty) {
        let struct_type = ix.symbols[t].kind == Kind::Type;
        return vars(ix, t)
            .filter_map(|m| {
                let s = &ix.symbols[m];
                let output = match s.kind {
                    Kind::Var(VarKind::Output) => true,
                    Kind::Var(VarKind::Input | VarKind::InOut) => false,
                    Kind::Field if struct_type => false,
                    _ => return None,
                };
                let detail = s.decl.lines().nth(1).unwrap_or(&s.decl).trim().to_string();
                Some(param(&s.name, output, detail))
            })
            .collect();
    }
    if let Some(fb) = sig::lookup_fb(ty) {
        let ins = fb.inputs.iter().map(|p| (p, false));
        let outs = fb.outputs.iter().map(|p| (p, true));
        return ins
            .chain(outs)
            .map(|(p, o)| param(p.name, o, format!("{} : {}", p.name, p.ty.name())))
            .collect();
    }
    Vec::new()
}

/// Inside `CAL inst(` / `FN(` at a parameter name's place: the formal
/// parameters of the instance's block or of the function.
fn call_params(
    ix: &Index,
    pou: Option<SymId>,
    text: &str,
    off: usize,
) -> Option<Vec<CompletionItem>> {
    let start = super::convert::floor_char(text, off.saturating_sub(CALL_LOOKBACK));
    let before = text.get(start..off)?;
    let mut depth = 0usize;
    let mut open = None;
    for (i, c) in before.char_indices().rev() {
        match c {
            ')' => depth += 1,
            '(' if depth == 0 => {
                open = Some(i);
                break;
            }
            '(' => depth -= 1,
            _ => {}
        }
    }
    let open = open?;
    // At a name's place: nothing but a name's start since `(` or `,`.
    let after = &before[open + 1..];
    let tail = after.rsplit(',').next().unwrap_or(after);
    if !tail
        .trim()
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || c == '_')
    {
        return None;
    }
    let head = before[..open].trim_end();
    let callee_start = head
        .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '.' || c == '&'))
        .map_or(0, |i| i + 1);
    let callee = &head[callee_start..];
    let op = head[..callee_start]
        .split_whitespace()
        .last()
        .unwrap_or("")
        .to_ascii_uppercase();
    let line_start = head[..callee_start].rfind('\n').map_or(0, |i| i + 1);
    let first_on_line = strip_label(head[line_start..callee_start].trim()).is_empty();
    if callee.is_empty()
        || (first_on_line && DEFERRABLE.contains(&callee.to_ascii_uppercase().as_str()))
    {
        return None;
    }
    if matches!(op.as_str(), "CAL" | "CALC" | "CALCN")
        && !first_on_line
        && let Some(ty) = pou.and_then(|p| chain_type(ix, p, callee))
    {
        return Some(type_members(ix, &ty, true));
    }
    let key = callee.to_ascii_uppercase();
    if let Some(&f) = ix.pou_by_name.get(&key) {
        return Some(type_members(
            ix,
            &ix.symbols[f].name.to_ascii_uppercase(),
            true,
        ));
    }
    let f = sig::lookup(callee)?;
    Some(
        f.params
            .iter()
            .map(|p| {
                let mut it = item(p.name, CompletionItemKind::PROPERTY, f.name);
                it.insert_text = Some(format!("{} := ", p.name));
                it
            })
            .collect(),
    )
}
