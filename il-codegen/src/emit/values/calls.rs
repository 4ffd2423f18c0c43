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
    ) -> TokenStream {
        let f = item_ident(name);
        // Arguments are evaluated into locals first: an indexed read may record
        // a fault in `__ctx`, which the call itself borrows.
        let ids: Vec<_> = (0..args.len()).map(|k| format_ident!("__a{}", k)).collect();
        let arg_lets: Vec<_> = args
            .iter()
            .zip(&ids)
            .map(|(a, id)| {
                let v = self.value(a, line);
                quote!(let #id = #v;)
            })
            .collect();
        let args = ids;
        let (io_lets, io_args, io_back) = self.bind_inouts(inouts, None, line);
        if out_types.is_empty() {
            if arg_lets.is_empty() && inouts.is_empty() {
                return quote!(#f(__ctx));
            }
            if inouts.is_empty() {
                return quote!({ #(#arg_lets)* #f(__ctx, #(#args,)*) });
            }
            return quote!({
                #(#arg_lets)* #io_lets
                let __r = #f(__ctx, #(#args,)* #(#io_args,)*);
                #io_back
                __r
            });
        }
        // Every output needs a place, read by `=>` or not.
        let ids: Vec<_> = (0..out_types.len())
            .map(|k| format_ident!("__o{}", k))
            .collect();
        let lets = out_types.iter().zip(&ids).map(|(t, id)| {
            let ty = rust_ty(t);
            let d = default_value(t);
            quote!(let mut #id: #ty = #d;)
        });
        let stores = outputs.iter().map(|(k, place, neg, w)| {
            let id = &ids[*k];
            let v = widened(if *neg { quote!(!#id) } else { quote!(#id) }, w);
            let v = self.fit_output(v, out_types.get(*k), place, line);
            self.write(place, v, line)
        });
        quote!({
            #(#arg_lets)*
            #io_lets
            #(#lets)*
            let __r = #f(__ctx, #(#args,)* #(#io_args,)* #(&mut #ids,)*);
            #io_back
            #(#stores)*
            __r
        })
    }

    /// The arguments for VAR_IN_OUT parameters: `&mut place` where the place
    /// is a plain path that no other argument (nor the called instance
    /// `avoid`) shares; otherwise a copy in a local written back after the
    /// call (array elements, the process image, aliased variables).
    pub(crate) fn bind_inouts(
        &self,
        places: &[Place],
        avoid: Option<&Place>,
        line: u32,
    ) -> (TokenStream, Vec<TokenStream>, TokenStream) {
        let mut lets = TokenStream::new();
        let mut back = TokenStream::new();
        let mut args = Vec::new();
        for (k, p) in places.iter().enumerate() {
            let shares = |q: &Place| q.root == p.root;
            let direct = !matches!(p.root, Root::Addr(_))
                && !Self::has_index(p)
                && !avoid.is_some_and(shares)
                && !places.iter().enumerate().any(|(j, q)| j != k && shares(q));
            if direct {
                let path = self.simple_path(p);
                args.push(quote!(&mut #path));
            } else {
                let id = format_ident!("__io{}", k);
                let ty = rust_ty(&p.ty);
                let v = self.read(p, line);
                lets.extend(quote!(let mut #id: #ty = #v;));
                back.extend(self.write(p, quote!(#id), line));
                args.push(quote!(&mut #id));
            }
        }
        (lets, args, back)
    }
}
