//! Partly specified addresses `AT %I*`, `%Q*`, `%M*` (Ed.2 2.4.1.1, and
//! TwinCAT's way of binding I/O): where they may stand and which types
//! their size letter allows. The variable itself is an ordinary field.

use super::Cx;
use super::codes::*;
use super::types::{Elem, Ty};
use crate::ast::{self, AddrSize, PouKind, VarKind};

/// Whether `AT a` (with `a.partial`) may declare a variable of `ty` in a
/// `kind` section of a `pou`; reports why not.
///
/// Ed.2 allows them in the VAR sections of PROGRAMs and FUNCTION_BLOCKs;
/// VAR_INPUT and VAR_OUTPUT are accepted too, as CODESYS-family tools do,
/// except under the 2nd edition (IL0304).
/// A FUNCTION has no memory to bind, VAR_TEMP lives for one call, and
/// VAR_IN_OUT / VAR_EXTERNAL refer to another variable.
pub(crate) fn allowed(
    cx: &mut Cx,
    pou: PouKind,
    kind: VarKind,
    a: &ast::DirectAddress,
    ty: &Ty,
) -> bool {
    let text = cx.file.snippet(a.span).to_string();
    let place = match (pou, kind) {
        (PouKind::Function, _) => Some("a FUNCTION (it has no memory between calls)"),
        (_, VarKind::Temp) => Some("VAR_TEMP (it lives for one call)"),
        (_, VarKind::Var | VarKind::Input | VarKind::Output) => None,
        _ => Some("this section"),
    };
    if let Some(place) = place {
        cx.err(
            BAD_ADDRESS,
            a.span,
            format!("a partly specified address `{text}` cannot be used in {place}: declare it in the VAR of a PROGRAM or FUNCTION_BLOCK"),
        );
        return false;
    }
    if let Some(section) = match kind {
        VarKind::Input => Some("VAR_INPUT"),
        VarKind::Output => Some("VAR_OUTPUT"),
        _ => None,
    } {
        let feature = crate::dialect::Feature::PartlyInInterface {
            text: text.clone(),
            section,
        };
        cx.feature(feature, a.span);
    }
    let fits = match (a.size, ty) {
        // `%I*` without size: any type (the host binds the whole variable).
        (AddrSize::Default, _) => true,
        (AddrSize::X, t) => *t == Ty::BOOL,
        (size, Ty::Elem(e)) => size_fits(size, *e),
        _ => false,
    };
    if !fits {
        cx.err(
            BAD_ADDRESS,
            a.span,
            format!("`{text}` has a size that {ty} does not have; write `%{}*` or the matching size letter", area_letter(a.area)),
        );
    }
    fits
}

/// Whether an address of `size` can hold an `e` (as for full addresses).
pub(crate) fn size_fits(size: AddrSize, e: Elem) -> bool {
    match size {
        AddrSize::Default | AddrSize::X => e == Elem::BOOL,
        AddrSize::B => matches!(e, Elem::BYTE | Elem::SINT | Elem::USINT),
        AddrSize::W => matches!(e, Elem::WORD | Elem::INT | Elem::UINT),
        AddrSize::D => matches!(e, Elem::DWORD | Elem::DINT | Elem::UDINT | Elem::REAL),
        AddrSize::L => matches!(e, Elem::LWORD | Elem::LINT | Elem::ULINT | Elem::LREAL),
    }
}

fn area_letter(a: ast::Area) -> char {
    match a {
        ast::Area::Input => 'I',
        ast::Area::Output => 'Q',
        ast::Area::Memory => 'M',
    }
}

/// VAR_GLOBAL takes full addresses only (Ed.2 2.7.1: `%I*` is completed by
/// VAR_CONFIG for variables inside programs and FBs): each `%I*` is
/// reported and dropped, so that the global is checked without it.
pub(crate) fn refuse_in_globals(cx: &mut Cx, block: &mut ast::VarBlock) {
    for d in &mut block.decls {
        if let Some(a) = d.location.as_ref().filter(|a| a.partial) {
            let text = cx.file.snippet(a.span).to_string();
            cx.err(
                BAD_ADDRESS,
                a.span,
                format!("a VAR_GLOBAL needs a full address, not `{text}`: partly specified addresses belong in the VAR of a PROGRAM or FUNCTION_BLOCK"),
            );
            d.location = None;
        }
    }
}
