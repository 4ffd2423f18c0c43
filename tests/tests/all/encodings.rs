//! `plc-encodings`: CODESYS V2.3 exports in Windows code pages, compiled by
//! build.rs (`Builder::encoding("windows-1251")`) and by `il!` (with
//! `encoding = "windows-1251"`, and the Windows-1252 one without a setting).
//! The files hold the code page's bytes: their STRING literals must come out
//! as the characters the engineer wrote.

use il_std::Cycle;
use il_tests::{encodings_build, encodings_macro};

#[test]
fn windows_1251_strings_through_build_rs_and_il() {
    let mut ctx = Cycle::new();
    let mut b = encodings_build::Nasos {
        pusk: true,
        ..Default::default()
    };
    b.call(&mut ctx);
    assert!(b.nasos);
    assert_eq!(b.soobshchenie.as_str(), Some("Насос"));
    let mut m = encodings_macro::Nasos {
        pusk: true,
        ..Default::default()
    };
    m.call(&mut ctx);
    assert!(m.nasos);
    assert_eq!(m.soobshchenie.as_str(), Some("Насос"));
}

#[test]
fn windows_1252_without_a_setting_through_il() {
    let mut ctx = Cycle::new();
    let mut a = encodings_macro::Anzeige::default();
    a.call(&mut ctx);
    assert_eq!(a.text.as_str(), Some("Größe"));
    // UTF-8 bytes, as for a UTF-8 source: `ö` and `ß` are two each.
    assert_eq!(a.n, 7);
}

#[test]
fn the_sources_are_not_utf8() {
    // What the tests above are about: the files hold the code pages' bytes.
    for f in [
        "plc-encodings/nasos_1251.exp",
        "plc-encodings/anzeige_1252.exp",
    ] {
        let bytes = std::fs::read(f).unwrap();
        assert!(std::str::from_utf8(&bytes).is_err(), "{f}");
    }
}
