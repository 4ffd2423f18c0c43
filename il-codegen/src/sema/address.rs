//! A direct address given as text by a host or a tool (`ilc run --set
//! %IW1=500`), resolved to the same [`Loc`] the checker gives the address in
//! a program: one decision of where `%IW1` lives in the process image.

use super::Cx;
use super::ir::Loc;
use super::resolve::resolve_addr;
use crate::diag::SourceFile;
use crate::syntax::lexer::{Tok, lex};

/// Resolve `%IX0.1`, `%QW3`, `%MD10` ... (a bit without size letter too) as
/// the checker resolves it in a body; the error says what is wrong with it.
pub fn parse_address(text: &str) -> Result<Loc, String> {
    let t = text.trim();
    let (toks, diags) = lex(t);
    if let Some(d) = diags.first() {
        return Err(format!("`{t}`: {}", d.message));
    }
    // Text outside a POU lexes as an orphan line: its markers and the line
    // end around the one token that must be the address.
    let mut real = toks
        .iter()
        .filter(|(_, tok, _)| !matches!(tok, Tok::Orphan | Tok::EndOrphan | Tok::Nl));
    let addr = match (real.next(), real.next()) {
        (Some((0, Tok::Addr(a), end)), None) if *end == t.len() => a.clone(),
        _ => return Err(format!("`{t}` is not a direct address like %IX0.1 or %QW2")),
    };
    let file = SourceFile::new("address", t.to_string());
    let mut cx = Cx {
        file: &file,
        diags: Vec::new(),
        standard: Default::default(),
        cr_steps: false,
        names: None,
    };
    match resolve_addr(&mut cx, &addr, None) {
        Some(l) if cx.diags.is_empty() => Ok(l),
        _ => Err(cx
            .diags
            .first()
            .map(|d| d.message.clone())
            .unwrap_or_else(|| format!("`{t}` is not a valid direct address"))),
    }
}

#[cfg(test)]
mod tests {
    use super::parse_address;
    use crate::ast::Area;
    use crate::sema::types::Elem;

    #[test]
    fn addresses_as_the_checker_resolves_them() {
        let l = parse_address("%IX1.3").unwrap();
        assert_eq!(
            (l.area, l.byte, l.bit, l.elem),
            (Area::Input, 1, Some(3), Elem::BOOL)
        );
        let l = parse_address("%QW3").unwrap();
        assert_eq!(
            (l.area, l.byte, l.bit, l.elem),
            (Area::Output, 6, None, Elem::WORD)
        );
        let l = parse_address("%MD2").unwrap();
        assert_eq!((l.byte, l.elem), (8, Elem::DWORD));
        assert_eq!(parse_address("%I9").unwrap().bit, Some(1));
        assert!(parse_address("%IX0.9").unwrap_err().contains("bit 9"));
        assert!(parse_address("%Z1").is_err());
        assert!(parse_address("%IW1 x").is_err());
        assert!(parse_address("start").is_err());
        assert!(
            parse_address("%IW99999999")
                .unwrap_err()
                .contains("outside")
        );
    }
}
