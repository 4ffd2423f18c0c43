//! The quick fix of a store into an undeclared name: declare it, with the
//! type of the current result, in the POU's `VAR` block (a new one after
//! the others when it has none).

use super::*;

impl Walk<'_, '_> {
    /// After `ST name` failed because `name` is undeclared (the last error
    /// is that, at the target): offer its declaration with the CR's type.
    pub(super) fn offer_declaration(&mut self, target: Span, cr: &Cr) {
        let Cr::Val(ty) = cr else { return };
        if !self.final_pass {
            return;
        }
        let text = &self.cx.file.text;
        let Some(name) = text.get(target.lo as usize..target.hi as usize) else {
            return;
        };
        if name.is_empty() || !name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_') {
            return;
        }
        let Some(fix) = declare(text, self.pou, name, ty) else {
            return;
        };
        if let Some(d) = self.cx.diags.last_mut()
            && d.code == UNKNOWN_NAME
            && d.span == target
        {
            d.fixes.push(fix);
        }
    }
}

/// The edit declaring `name : ty;` in `pou`: before the `END_VAR` of its
/// last plain `VAR` block, or in a new block after its last block (or its
/// header).
fn declare(text: &str, pou: &ast::Pou, name: &str, ty: &Ty) -> Option<crate::diag::Fix> {
    let title = format!("Declare `{name} : {ty}` in VAR");
    let nl = if text.contains("\r\n") { "\r\n" } else { "\n" };
    let block = pou
        .var_blocks
        .iter()
        .rev()
        .find(|b| b.kind == ast::VarKind::Var && !b.constant);
    let edit = if let Some(b) = block {
        let end_var = (b.span.hi as usize).checked_sub("END_VAR".len())?;
        let line_start = text[..end_var].rfind('\n').map_or(0, |i| i + 1);
        if text[line_start..end_var].trim().is_empty() {
            (
                Span::new(line_start, line_start),
                format!("    {name} : {ty};{nl}"),
            )
        } else {
            // `VAR x : INT; END_VAR` on one line.
            (Span::new(end_var, end_var), format!("{name} : {ty}; "))
        }
    } else {
        let after = pou
            .var_blocks
            .last()
            .map(|b| b.span.hi)
            .or_else(|| pou.return_type.as_ref().map(|t| t.span().hi))
            .unwrap_or(pou.name.span.hi) as usize;
        let line_end = text[after..]
            .find('\n')
            .map_or(text.len(), |i| after + i + 1);
        let block = format!("VAR{nl}    {name} : {ty};{nl}END_VAR{nl}");
        if line_end == text.len() && !text.ends_with('\n') {
            (Span::new(line_end, line_end), format!("{nl}{block}"))
        } else {
            (Span::new(line_end, line_end), block)
        }
    };
    Some(crate::diag::Fix {
        title,
        edits: vec![edit],
    })
}
