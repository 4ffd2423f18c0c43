//! Calls of user FUNCTIONs and in-out bindings.

use super::*;

impl PouEmitter<'_> {
    /// A call of a user FUNCTION; every output gets a place, read by `=>` or not.
    pub(super) fn user_call(
        &self,
        name: &str,
        args: &[Value],
        inouts: &[Place],
        outputs: &[(usize, Place, bool, Option<Widen>)],
        out_types: &[Ty],
        line: u32,
    ) -> String {
        let f = item_ident(name);
        // Arguments are evaluated into locals first: an indexed read may record
        // a fault in `__ctx`, which the call itself borrows.
        let arg_lets: String = args
            .iter()
            .enumerate()
            .map(|(k, a)| format!("let __a{k} = {};", self.value(a, line)))
            .collect();
        let args = tail((0..args.len()).map(|k| format!("__a{k}")));
        let (io_lets, io_args, io_back) =
            self.bind_inouts(&inouts.iter().collect::<Vec<_>>(), None, line);
        let io_args = tail(io_args);
        if out_types.is_empty() {
            if arg_lets.is_empty() && inouts.is_empty() {
                return format!("{f}(__ctx)");
            }
            if inouts.is_empty() {
                return format!("{{ {arg_lets} {f}(__ctx{args}) }}");
            }
            return format!(
                "{{ {arg_lets} {io_lets} let __r = {f}(__ctx{args}{io_args}); {io_back} __r }}"
            );
        }
        // Every output needs a place, read by `=>` or not.
        let lets: String = out_types
            .iter()
            .enumerate()
            .map(|(k, t)| format!("let mut __o{k}: {} = {};", rust_ty(t), default_value(t)))
            .collect();
        let stores: String = outputs
            .iter()
            .map(|(k, place, neg, w)| {
                let id = format!("__o{k}");
                let v = widened(if *neg { format!("!{id}") } else { id }, w);
                let v = self.fit_output(v, out_types.get(*k), place, line);
                self.write(place, v, line)
            })
            .collect();
        let outs = tail((0..out_types.len()).map(|k| format!("&mut __o{k}")));
        format!(
            "{{ {arg_lets} {io_lets} {lets} let __r = {f}(__ctx{args}{io_args}{outs}); {io_back} {stores} __r }}"
        )
    }

    /// The arguments for VAR_IN_OUT parameters: `&mut place` where the place
    /// is a plain path that no other argument (nor the called instance
    /// `avoid`) shares; otherwise a copy in a local written back after the
    /// call (array elements, the process image, aliased variables).
    pub(crate) fn bind_inouts(
        &self,
        places: &[&Place],
        avoid: Option<&Place>,
        line: u32,
    ) -> (String, Vec<String>, String) {
        let mut lets = String::new();
        let mut back = String::new();
        let mut args = Vec::new();
        for (k, p) in places.iter().enumerate() {
            let shares = |q: &Place| q.root == p.root;
            let direct = !matches!(p.root, Root::Addr(_))
                && !Self::has_index(p)
                && !avoid.is_some_and(shares)
                && !places.iter().enumerate().any(|(j, q)| j != k && shares(q));
            if direct {
                args.push(format!("&mut {}", self.simple_path(p)));
            } else {
                let id = format!("__io{k}");
                let ty = rust_ty(&p.ty);
                let v = self.read(p, line);
                lets.push_str(&format!("let mut {id}: {ty} = {v};"));
                back.push_str(&self.write(p, id.clone(), line));
                args.push(format!("&mut {id}"));
            }
        }
        (lets, args, back)
    }
}
