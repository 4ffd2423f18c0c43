//! The initialization option `dialect`: `.il` documents are M221 /
//! TwidoSuite listings, checked as `ilc check --dialect m221` checks them.

use super::*;

#[test]
fn m221_listings_are_checked_with_the_dialect_option() {
    let dir = temp_dir("dialect-m221");
    let text = "LD %I0.0\nST %Q0.0\n\nBLK %TM0\nLD %I0.1\nIN\nEND_BLK\n";
    std::fs::write(dir.join("main.il"), text).unwrap();
    let main = uri(&dir.join("main.il"));
    // As IEC IL the listing is no program; as an M221 listing its one
    // problem is the timer without configuration, on its line.
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({"dialect": "m221"}));
    let d = c.diagnostics_for(&main);
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0]["code"], "IL0436");
    assert_eq!(
        d[0]["range"]["start"],
        json!({"line": 3, "character": 4}),
        "{d:?}"
    );
    c.finish();
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({}));
    let d = c.diagnostics_for(&main);
    assert!(d.iter().all(|x| x["code"] != "IL0436"), "{d:?}");
    assert!(!d.is_empty());
    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}
