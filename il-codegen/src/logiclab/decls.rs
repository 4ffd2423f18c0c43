//! How a variable, a member and a data type of a LogicLab project are
//! written: the `type`, `length`, `dim0` ... attributes as an IL type, an
//! `<initValue>`, an `<address>`; structs, enums, typedefs and subranges as
//! `TYPE ... END_TYPE`. Every piece is mapped to the element it stands for;
//! what cannot be written is reported and left out whole.

use roxmltree::Node;

use super::codes::{BAD_PROJECT, BAD_VALUE, NOT_IEC_ADDRESS};
use super::lx::Lx;
use super::read::{TypeKind, attr_span, checked, is, kid, kids, tag};
use crate::diag::Diagnostic;
use crate::plcopen::text::{attr_into, content_range, start_tag};
use crate::plcopen::validate::{self, Kind, shown};

impl Lx<'_> {
    /// Generated text standing for element `n`'s start tag.
    pub(super) fn put(&mut self, s: &str, n: Node) {
        let r = start_tag(self.xml, n.range());
        self.w.gen_at(s, r);
    }

    /// The IL type of a variable, member or typedef (`type`, `length`,
    /// `dim0` ... attributes), or `None` (reported).
    pub(super) fn type_text(&mut self, v: Node) -> Option<String> {
        // The string types are keywords, and names no other way.
        let base = match v.attribute("type") {
            Some(t) if ["STRING", "WSTRING"].contains(&t.to_ascii_uppercase().as_str()) => t,
            _ => checked(self.xml, v, "type", Kind::Name, &mut self.diags)?,
        };
        let mut ty = self
            .renamed
            .get(&base.to_ascii_uppercase())
            .cloned()
            .unwrap_or_else(|| base.to_string());
        if v.attribute("length").is_some() {
            let n = checked(self.xml, v, "length", Kind::Count, &mut self.diags)?;
            ty = format!("{ty}[{n}]");
        }
        let mut dims = Vec::new();
        for d in ["dim0", "dim1", "dim2"] {
            if v.attribute(d).is_none() {
                break;
            }
            let n = checked(self.xml, v, d, Kind::Count, &mut self.diags)?;
            match n.parse::<u64>() {
                Ok(n) if n > 0 => dims.push(format!("0..{}", n - 1)),
                _ => {
                    self.diags.push(
                        Diagnostic::error(
                            BAD_VALUE,
                            attr_span(self.xml, v, d),
                            format!("array size `{d}=\"{}\"` is not a positive number", shown(n)),
                        )
                        .with_label("expected at least 1"),
                    );
                    return None;
                }
            }
        }
        if !dims.is_empty() {
            ty = format!("ARRAY[{}] OF {ty}", dims.join(", "));
        }
        Some(ty)
    }

    /// The initial value of `v` (`<initValue>`), written after ` := `;
    /// false when there is one that is not a value (reported).
    fn init(&mut self, v: Node) -> bool {
        let Some(iv) = kid(v, "initValue") else {
            return true;
        };
        let value = iv.text().unwrap_or("").trim();
        if value.is_empty() {
            return true;
        }
        if let Err(why) = validate::check(Kind::Value, value) {
            self.diags.push(
                Diagnostic::error(
                    BAD_VALUE,
                    tag(self.xml, iv),
                    format!(
                        "the initial value `{}` is not {}: {why}",
                        shown(value),
                        Kind::Value.what()
                    ),
                )
                .with_label("not a value")
                .with_note("the variable is left out"),
            );
            return false;
        }
        let raw = content_range(self.xml, iv.range());
        let lead = self.xml[raw.clone()].len() - self.xml[raw.clone()].trim_start().len();
        let start = raw.start + lead;
        let end = start + self.xml[start..raw.end].trim_end().len();
        self.put(" := ", iv);
        attr_into(&mut self.w, self.xml, start..end, value);
        true
    }

    /// ` AT %QX1.5` for a bit address; other addresses are data block
    /// positions, not IEC addresses (a warning).
    fn address(&mut self, v: Node, name: &str) {
        let Some(a) = kid(v, "address") else { return };
        let get = |k: &str| a.attribute(k).unwrap_or("");
        let (area, size, index, sub) = (get("type"), get("typeVar"), get("index"), get("subIndex"));
        let bit = size.eq_ignore_ascii_case("X")
            && sub.parse::<u8>().is_ok_and(|b| b <= 7)
            && index.parse::<u32>().is_ok();
        let text = format!("%{area}{size}{index}.{sub}");
        if bit && validate::check(Kind::Address, &text).is_ok() {
            self.put(&format!(" AT {text}"), a);
            return;
        }
        self.diags.push(
            Diagnostic::warning(
                NOT_IEC_ADDRESS,
                tag(self.xml, a),
                format!(
                    "`{name}` is located at `{}`, a position in a LogicLab data block, not an IEC address: compiled without it",
                    shown(&text)
                ),
            )
            .with_label("not bound")
            .with_note("the host reads or writes it and binds it to the target itself"),
        );
    }

    /// `\tname [AT %..] : TYPE [:= value];` for a `<var>` or `<const>`;
    /// nothing (reported) when part of it cannot be written.
    pub(super) fn var_line(&mut self, v: Node) -> bool {
        let mark = self.w.mark();
        let ok = (|| {
            let name = checked(self.xml, v, "name", Kind::Name, &mut self.diags)?.to_string();
            self.put("\t", v);
            let r = v.attributes().find(|a| a.name() == "name")?.range_value();
            attr_into(&mut self.w, self.xml, r, &name);
            self.address(v, &name);
            let ty = self.type_text(v)?;
            self.w
                .gen_at(&format!(" : {ty}"), attr_span(self.xml, v, "type").range());
            self.init(v).then_some(())?;
            self.put(";\n", v);
            Some(())
        })()
        .is_some();
        if !ok {
            self.w.rollback(mark);
        }
        ok
    }

    pub(super) fn data_type(&mut self, n: Node, kind: TypeKind, name: &str) {
        let mark = self.w.mark();
        self.put("TYPE ", n);
        attr_into(
            &mut self.w,
            self.xml,
            attr_span(self.xml, n, "name").range(),
            name,
        );
        let ok = match kind {
            TypeKind::Struct => {
                self.put(" : STRUCT\n", n);
                let members: Vec<Node> = kids(n, "vars")
                    .flat_map(|v| v.children())
                    .filter(|c| is(c, "var"))
                    .collect();
                let all = members.iter().all(|m| self.var_line(*m));
                self.put("END_STRUCT;\n", n);
                all && !members.is_empty() || self.empty(n, "members")
            }
            TypeKind::Enum => self.enum_values(n),
            TypeKind::Typedef => match self.type_text(n) {
                Some(ty) => {
                    self.put(&format!(" : {ty};\n"), n);
                    true
                }
                None => false,
            },
            TypeKind::Subrange => self.subrange(n),
        };
        if ok {
            self.put("END_TYPE\n\n", n);
        } else {
            self.w.rollback(mark);
        }
    }

    fn empty(&mut self, n: Node, what: &str) -> bool {
        self.diags.push(
            Diagnostic::error(
                BAD_PROJECT,
                tag(self.xml, n),
                format!("`<{}>` has no {what}", n.tag_name().name()),
            )
            .with_label(format!("no {what}"))
            .with_note("the type is left out"),
        );
        false
    }

    fn enum_values(&mut self, n: Node) -> bool {
        let elements: Vec<Node> = kids(n, "elements")
            .flat_map(|e| kids(e, "element"))
            .collect();
        if elements.is_empty() {
            return self.empty(n, "elements");
        }
        self.put(" : (", n);
        for (i, e) in elements.iter().enumerate() {
            let Some(name) = checked(self.xml, *e, "name", Kind::Name, &mut self.diags) else {
                return false;
            };
            if i > 0 {
                self.put(", ", *e);
            }
            attr_into(
                &mut self.w,
                self.xml,
                attr_span(self.xml, *e, "name").range(),
                name,
            );
            if let Some(v) = kid(*e, "value") {
                let value = v.text().unwrap_or("").trim();
                if validate::check(Kind::Integer, value).is_err() {
                    return self.bad_text(v, value, Kind::Integer);
                }
                self.put(&format!(" := {value}"), v);
            }
        }
        self.put(");\n", n);
        true
    }

    fn subrange(&mut self, n: Node) -> bool {
        let Some(ty) = self.type_text(n) else {
            return false;
        };
        let mut bounds = Vec::new();
        for b in ["minValue", "maxValue"] {
            let Some(v) = kid(n, b) else {
                return self.empty(n, &format!("`<{b}>`"));
            };
            let value = v.text().unwrap_or("").trim();
            if validate::check(Kind::Integer, value).is_err() {
                return self.bad_text(v, value, Kind::Integer);
            }
            bounds.push(value.to_string());
        }
        self.put(&format!(" : {ty} ({}..{});\n", bounds[0], bounds[1]), n);
        true
    }

    fn bad_text(&mut self, n: Node, value: &str, kind: Kind) -> bool {
        self.diags.push(
            Diagnostic::error(
                BAD_VALUE,
                tag(self.xml, n),
                format!("`{}` is not {}", shown(value), kind.what()),
            )
            .with_label(format!("expected {}", kind.what()))
            .with_note("the element is left out"),
        );
        false
    }
}
