//! Finding child elements by name, for the PLCopen, LogicLab and M221
//! translations, which all walk roxmltree's tree.

use roxmltree::Node;

/// `n` is an element named `name` (namespaces aside).
pub(crate) fn is(n: &Node, name: &str) -> bool {
    n.is_element() && n.tag_name().name() == name
}

/// The child elements of `n` named `name`.
pub(crate) fn kids<'a, 'i>(
    n: Node<'a, 'i>,
    name: &'static str,
) -> impl Iterator<Item = Node<'a, 'i>> {
    // One step per child our code looks at (roxmltree's parse is not ours).
    n.children().filter(move |c| {
        crate::step_counter::add(1);
        is(c, name)
    })
}

/// The first child element of `n` named `name`.
pub(crate) fn kid<'a, 'i>(n: Node<'a, 'i>, name: &'static str) -> Option<Node<'a, 'i>> {
    kids(n, name).next()
}
