//! `ilc run --vcd` and `--plot`: the dump, parsed back with the `vcd` crate,
//! holds at each time step what the table shows; the timing diagram is
//! well-formed SVG with one lane per watched signal.

use std::path::PathBuf;
use std::process::{Command, Output};

use vcd::{Command as Vc, IdCode, ScopeItem, TimescaleUnit};

const WAVES: &str = "\
TYPE
    Mode : (Off, Slow := 5, Fast);
    Pt : STRUCT x : INT; lit : BOOL; END_STRUCT;
END_TYPE
PROGRAM Waves
VAR_INPUT
    go : BOOL;
    mode : Mode;
END_VAR
VAR
    n : DINT := 2;
    u : UDINT;
    b : BYTE := 16#F0;
    r : REAL := 0.75;
    lr : LREAL := -1.5;
    p : Pt;
    a : ARRAY[0..2] OF INT;
    m : ARRAY[1..2, 1..2] OF SINT;
    s : STRING[10] := 'ab';
    t1 : TON;
    lamp AT %QX0.1 : BOOL;
END_VAR
    LD n
    SUB 1
    ST n
    DINT_TO_INT
    ST p.x
    ST a[1]
    INT_TO_SINT
    ST m[2, 1]
    LD u
    ADD 1
    ST u
    LD r
    MUL 2.0
    ST r
    LD lr
    MUL 2.0
    ST lr
    LD b
    ROL 1
    ST b
    LD go
    ST p.lit
    CAL t1(IN := go, PT := T#30ms)
    LD t1.Q
    ST lamp
END_PROGRAM
";

fn dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("ilc_waves");
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn file(name: &str, text: &str) -> String {
    let p = dir().join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

fn ilc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .expect("run ilc")
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// A variable read back: path joined by `.`, type, width and changes.
type Var = (String, String, u32, Vec<(u64, Vc)>);

/// A dump read back.
struct Dump {
    timescale: Option<(u32, TimescaleUnit)>,
    vars: Vec<Var>,
    comments: Vec<(u64, String)>,
}

impl Dump {
    fn read(path: &str) -> Dump {
        let f = std::io::BufReader::new(std::fs::File::open(path).unwrap());
        let mut p = vcd::Parser::new(f);
        let h = p.parse_header().unwrap();
        let mut vars = Vec::new();
        let mut codes: Vec<IdCode> = Vec::new();
        fn walk(
            items: &[ScopeItem],
            path: &mut Vec<String>,
            vars: &mut Vec<Var>,
            codes: &mut Vec<IdCode>,
        ) {
            for it in items {
                match it {
                    ScopeItem::Scope(s) => {
                        path.push(s.identifier.clone());
                        walk(&s.items, path, vars, codes);
                        path.pop();
                    }
                    ScopeItem::Var(v) => {
                        let mut p = path.clone();
                        p.push(v.reference.clone());
                        vars.push((p.join("."), v.var_type.to_string(), v.size, Vec::new()));
                        codes.push(v.code);
                    }
                    _ => {}
                }
            }
        }
        walk(&h.items, &mut Vec::new(), &mut vars, &mut codes);
        let (mut now, mut comments) = (0u64, Vec::new());
        for c in p {
            let c = c.unwrap();
            let code = match &c {
                Vc::Timestamp(t) => {
                    now = *t;
                    continue;
                }
                Vc::Comment(s) => {
                    comments.push((now, s.clone()));
                    continue;
                }
                Vc::ChangeScalar(i, _)
                | Vc::ChangeVector(i, _)
                | Vc::ChangeReal(i, _)
                | Vc::ChangeString(i, _) => *i,
                _ => continue,
            };
            let k = codes.iter().position(|x| *x == code).expect("declared id");
            vars[k].3.push((now, c));
        }
        Dump {
            timescale: h.timescale,
            vars,
            comments,
        }
    }

    fn var(&self, path: &str) -> &Var {
        self.vars
            .iter()
            .find(|v| v.0 == path)
            .unwrap_or_else(|| panic!("no {path} in {:?}", self.names()))
    }

    fn names(&self) -> Vec<&str> {
        self.vars.iter().map(|v| v.0.as_str()).collect()
    }

    /// The value at time `t`, as text to compare with a table cell.
    fn at(&self, path: &str, t: u64) -> String {
        let (_, ty, width, changes) = self.var(path);
        let c = changes
            .iter()
            .rev()
            .find(|(ct, _)| *ct <= t)
            .map(|(_, c)| c)
            .unwrap_or_else(|| panic!("{path} has no value at {t}"));
        match c {
            Vc::ChangeScalar(_, v) => (if *v == vcd::Value::V1 { "1" } else { "0" }).into(),
            Vc::ChangeVector(_, v) => {
                let mut b = 0u64;
                for x in v.iter() {
                    b = b << 1 | (x == vcd::Value::V1) as u64;
                }
                // Wires hold the bits; the table shows signed types signed.
                let signed = ty == "wire" && path_is_signed(path);
                if signed && *width < 64 && b >> (width - 1) & 1 == 1 {
                    ((b as i64) - (1i64 << width)).to_string()
                } else {
                    b.to_string()
                }
            }
            Vc::ChangeReal(_, r) => r.to_string(),
            Vc::ChangeString(_, s) => s.clone(),
            other => panic!("{other:?}"),
        }
    }
}

fn path_is_signed(path: &str) -> bool {
    ["Waves.n", "Waves.p.x", "Waves.a[1]", "Waves.m[2,1]"].contains(&path)
}

/// A table cell as the dump writes it: BOOL as 0/1, TIME as ms (the
/// timescale unit of a 10 ms step), enumerations as their value, strings bare.
fn cell_as_dump(cell: &str) -> String {
    match cell {
        "TRUE" => "1".into(),
        "FALSE" => "0".into(),
        _ if cell.starts_with("T#") => {
            let t = &cell[2..];
            let ms = if let Some(ms) = t.strip_suffix("ms") {
                ms.parse::<u64>().unwrap()
            } else if t == "0s" {
                0
            } else {
                panic!("unexpected duration {cell}")
            };
            ms.to_string()
        }
        "Mode#Off" => "0".into(),
        "Mode#Slow" => "5".into(),
        "Mode#Fast" => "6".into(),
        _ if cell.starts_with('\'') => cell.trim_matches('\'').to_string(),
        // Reals: the same number (the table prints f32 as f32, the dump as f64).
        _ if cell.contains('.') => (cell.parse::<f32>().unwrap() as f64).to_string(),
        _ => cell.to_string(),
    }
}

const WATCH: &str = "go,mode,n,u,b,r,lr,p.x,p.lit,a[1],s,t1.ET,t1.Q,%QX0.1";

#[test]
fn vcd_holds_what_the_table_shows_at_every_step() {
    let src = file("waves.il", WAVES);
    // Its own folder: other tests write their temporaries meanwhile.
    let own = dir().join("table");
    std::fs::create_dir_all(&own).unwrap();
    let out = own.join("waves.vcd").display().to_string();
    let o = ilc(&[
        "run",
        &src,
        "--cycles",
        "7",
        "--set",
        "go=TRUE@2",
        "--set",
        "mode=Fast@3",
        "--set",
        "mode=Slow@5",
        "--set",
        "go=FALSE@7",
        "--watch",
        WATCH,
        "--vcd",
        &out,
    ]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let table = text(&o.stdout);
    let d = Dump::read(&out);
    assert_eq!(d.timescale, Some((1, TimescaleUnit::MS)));
    let mut lines = table.lines();
    let header: Vec<&str> = lines.next().unwrap().split_whitespace().collect();
    assert_eq!(header.len(), 2 + WATCH.split(',').count());
    let mut rows = 0;
    for line in lines {
        let cells: Vec<&str> = line.split_whitespace().collect();
        assert_eq!(cells.len(), header.len(), "{line}");
        let k: u64 = cells[0].parse().unwrap();
        let t = (k - 1) * 10;
        assert_eq!(
            cells[1],
            if t == 0 {
                "0s".to_string()
            } else {
                format!("{t}ms")
            }
        );
        for (name, cell) in header[2..].iter().zip(&cells[2..]) {
            // Members are in the scope of their instance or STRUCT.
            let path = format!("Waves.{name}");
            assert_eq!(
                d.at(&path, t),
                cell_as_dump(cell),
                "{name} at {t} ms\n{table}"
            );
        }
        rows += 1;
    }
    assert_eq!(rows, 7);
    // Declarations: wires of the IEC width, reals, integers for TIME and enums.
    let decl = |p: &str| {
        let v = d.var(p);
        (v.1.as_str(), v.2)
    };
    assert_eq!(decl("Waves.go"), ("wire", 1));
    assert_eq!(decl("Waves.n"), ("wire", 32));
    assert_eq!(decl("Waves.b"), ("wire", 8));
    assert_eq!(decl("Waves.a[1]"), ("wire", 16));
    assert_eq!(decl("Waves.r"), ("real", 64));
    assert_eq!(decl("Waves.t1.ET"), ("integer", 64));
    assert_eq!(decl("Waves.mode"), ("integer", 64));
    assert_eq!(decl("Waves.s"), ("string", 1));
    // Each enumeration change is named in a comment at its time.
    assert!(
        d.comments.contains(&(20, "mode = Fast".to_string())),
        "{:?}",
        d.comments
    );
    assert!(
        d.comments.contains(&(40, "mode = Slow".to_string())),
        "{:?}",
        d.comments
    );
    // `n` decrements every scan: a change at each step; `s` never changes.
    assert_eq!(d.var("Waves.n").3.len(), 7);
    assert_eq!(d.var("Waves.s").3.len(), 1);
    // No temporary file is left beside it.
    let stray: Vec<_> = std::fs::read_dir(&own)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().ends_with(".tmp"))
        .collect();
    assert!(stray.is_empty(), "{stray:?}");
}

#[test]
fn whole_structs_and_arrays_are_scopes_and_elements() {
    let src = file("waves_whole.il", WAVES);
    let out = dir().join("whole.vcd").display().to_string();
    let o = ilc(&[
        "run",
        &src,
        "--cycles",
        "2",
        "--watch",
        "p,a,m,t1.Q",
        "--vcd",
        &out,
    ]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let d = Dump::read(&out);
    assert_eq!(
        d.names(),
        [
            "Waves.p.x",
            "Waves.p.lit",
            "Waves.a[0]",
            "Waves.a[1]",
            "Waves.a[2]",
            "Waves.m[1,1]",
            "Waves.m[1,2]",
            "Waves.m[2,1]",
            "Waves.m[2,2]",
            "Waves.t1.Q"
        ]
    );
    // m[2, 1] := SINT of n, which is 0 after the second scan.
    assert_eq!(d.var("Waves.m[2,1]").2, 8);
    assert_eq!(d.at("Waves.m[2,1]", 0), "1");
    assert_eq!(d.at("Waves.m[2,1]", 10), "0");
    assert_eq!(d.at("Waves.a[1]", 10), "0");
}

#[test]
fn timescale_follows_the_step() {
    let src = file("waves_step.il", WAVES);
    for (step, unit, per_scan) in [
        ("250us", TimescaleUnit::US, 250u64),
        ("2s", TimescaleUnit::S, 2),
        ("T#1s500ms", TimescaleUnit::MS, 1500),
    ] {
        let out = dir().join(format!("step_{step}.vcd").replace('#', "_"));
        let out = out.display().to_string();
        let o = ilc(&[
            "run", &src, "--cycles", "3", "--step", step, "--watch", "n,t1.PT", "--vcd", &out,
        ]);
        assert!(o.status.success(), "{}", text(&o.stderr));
        let d = Dump::read(&out);
        assert_eq!(d.timescale, Some((1, unit)), "{step}");
        let times: Vec<u64> = d.var("Waves.n").3.iter().map(|c| c.0).collect();
        assert_eq!(times, [0, per_scan, 2 * per_scan], "{step}");
    }
}

#[test]
fn a_failed_run_leaves_the_old_file() {
    let src = file("waves_fail.il", WAVES);
    let out = dir().join("kept.vcd");
    std::fs::write(&out, "old").unwrap();
    let o = ilc(&[
        "run",
        &src,
        "--watch",
        "n,nosuch",
        "--vcd",
        &out.display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "old");
    let o = ilc(&["run", &src, "--vcd", "/nonexistent-dir/x.vcd"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        text(&o.stderr).contains("--vcd /nonexistent-dir/x.vcd"),
        "{}",
        text(&o.stderr)
    );
}

#[test]
fn plot_is_svg_with_one_lane_per_signal() {
    let src = file("waves_plot.il", WAVES);
    let out = dir().join("waves.svg").display().to_string();
    let watch = "go,mode,n,r,p.lit,a[1],s,t1.ET,%QX0.1";
    let o = ilc(&[
        "run",
        &src,
        "--cycles",
        "6",
        "--set",
        "go=TRUE@2",
        "--set",
        "mode=Fast@3",
        "--watch",
        watch,
        "--plot",
        &out,
    ]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let svg = std::fs::read_to_string(&out).unwrap();
    let doc = roxmltree::Document::parse(&svg).expect("well-formed XML");
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    let texts: Vec<(String, String)> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .map(|n| {
            (
                n.attribute("x").unwrap_or("").to_string(),
                n.text().unwrap_or("").trim().to_string(),
            )
        })
        .collect();
    // The lane labels are the texts in the left column, after the title.
    let labels: Vec<&str> = texts
        .iter()
        .filter(|(x, _)| x == "8")
        .map(|(_, t)| t.as_str())
        .skip(1)
        .collect();
    assert_eq!(labels, watch.split(',').collect::<Vec<_>>());
    // One stepped trace per lane, and the axis in ms.
    let traces = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke-width") == Some("2"))
        .count();
    assert_eq!(traces, labels.len());
    assert!(texts.iter().any(|(_, t)| t == "time (ms)"), "{texts:?}");
    // The enumeration's values are written on its lane.
    assert!(texts.iter().any(|(_, t)| t == "Fast"), "{texts:?}");
}

/// The README's timing diagram is what the command beside it draws
/// (refresh with `IL_BLESS=1`).
#[test]
fn readme_picture_is_up_to_date() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let cmd = "ilc run examples/plc/traffic_light.il --program TrafficLight --cycles 36 --step 500ms \\\n    --set enable=TRUE --set enable=FALSE@29 \\\n    --watch enable,red,yellow,green,phase,step.ET --plot docs/traffic-light-timing.svg";
    assert!(
        readme.contains(cmd),
        "README.md no longer shows the command"
    );
    let out = dir().join("readme.svg").display().to_string();
    let src = root
        .join("examples/plc/traffic_light.il")
        .display()
        .to_string();
    let o = ilc(&[
        "run",
        &src,
        "--program",
        "TrafficLight",
        "--cycles",
        "36",
        "--step",
        "500ms",
        "--set",
        "enable=TRUE",
        "--set",
        "enable=FALSE@29",
        "--watch",
        "enable,red,yellow,green,phase,step.ET",
        "--plot",
        &out,
    ]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let got = std::fs::read_to_string(&out).unwrap();
    let committed = root.join("docs/traffic-light-timing.svg");
    if std::env::var_os("IL_BLESS").is_some() {
        std::fs::write(&committed, &got).unwrap();
    }
    assert!(
        std::fs::read_to_string(&committed).ok().as_deref() == Some(got.as_str()),
        "docs/traffic-light-timing.svg is out of date; refresh it with `IL_BLESS=1 cargo test -p il-cli --test all waves`"
    );
}

#[test]
fn an_element_of_a_2d_array_is_one_watched_name() {
    let src = file("waves_elem.il", WAVES);
    let o = ilc(&["run", &src, "--cycles", "2", "--watch", "m[2,1],n"]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let header = stdout.lines().next().unwrap_or_default();
    assert!(
        header.contains("m[2,1]") && header.contains('n'),
        "{stdout}"
    );
    // n counts down from 2 and m[2, 1] takes it: 1 after scan 1, 0 after scan 2.
    let rows: Vec<Vec<&str>> = stdout
        .lines()
        .skip(1)
        .map(|l| l.split_whitespace().collect())
        .filter(|r: &Vec<&str>| r.first().is_some_and(|c| c.parse::<u32>().is_ok()))
        .collect();
    assert_eq!(rows.len(), 2, "{stdout}");
    assert_eq!(&rows[0][2..], ["1", "1"], "{stdout}");
    assert_eq!(&rows[1][2..], ["0", "0"], "{stdout}");
}

/// `--vcd FILE.vcd` writes `FILE.gtkw` beside it: read back, it names the
/// dump, adds every watched signal in order with integers as signed decimal
/// (GTKWave's flags 0x424) and BOOL as binary, shows the enumeration through
/// a translate file holding its value names, and is zoomed so that the run
/// fits (GTKWave shows 2^-zoom ticks per 200 pixels).
#[test]
fn vcd_comes_with_a_gtkwave_save_file() {
    let src = file(
        "gtkw.il",
        "TYPE Phase : (Idle, Filling, Full); END_TYPE\n\
         PROGRAM Fill\nVAR go : BOOL; level : INT := -3; phase : Phase; lamp AT %QX0.1 : BOOL; END_VAR\n\
         LD go\nJMPCN done\nLD level\nADD 10\nST level\nLD Phase#Filling\nST phase\n\
         LD level\nGT 20\nJMPCN done\nLD Phase#Full\nST phase\ndone:\nEND_PROGRAM\n",
    );
    let vcd = dir().join("fill.vcd");
    let out = ilc(&[
        "run",
        &src,
        "--cycles",
        "40",
        "--step",
        "100ms",
        "--set",
        "go=TRUE@3",
        "--watch",
        "go,level,phase,%QX0.1",
        "--vcd",
        vcd.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let save = std::fs::read_to_string(dir().join("fill.gtkw")).expect("fill.gtkw");
    assert!(
        save.contains(&format!("[dumpfile] \"{}\"", vcd.display())),
        "{save}"
    );
    let traces: Vec<&str> = save.lines().filter(|l| l.starts_with("Fill.")).collect();
    assert_eq!(
        traces,
        ["Fill.go", "Fill.level[15:0]", "Fill.phase"],
        "{save}"
    );
    // GTKWave names an address with a `.` as an escaped identifier; the
    // trace shows it unescaped through an alias.
    assert!(
        save.lines().any(|l| l == "+{%QX0.1} Fill.\\%QX0.1"),
        "{save}"
    );
    let flags = |trace: &str| {
        let lines: Vec<&str> = save.lines().collect();
        let i = lines.iter().position(|l| *l == trace).unwrap();
        lines[i - 1].to_string()
    };
    assert_eq!(flags("Fill.go"), "@28");
    assert_eq!(flags("Fill.level[15:0]"), "@424");
    assert_eq!(flags("Fill.phase"), "@2024");
    let filter = save
        .lines()
        .find_map(|l| l.strip_prefix("^1 "))
        .expect("a translate file for the enumeration");
    let names = std::fs::read_to_string(filter).unwrap();
    assert!(names.lines().any(|l| l == "0 Idle"), "never shown: {names}");
    assert!(names.lines().any(|l| l == "1 Filling"), "{names}");
    assert!(names.lines().any(|l| l == "2 Full"), "{names}");
    // The dump ends at the last scan, though nothing changes after 600 ms,
    // so that GTKWave's time axis covers the run.
    let dump = std::fs::read_to_string(&vcd).unwrap();
    let last = dump.lines().rev().find(|l| l.starts_with('#'));
    assert_eq!(last, Some("#3900"), "{dump}");
    // 40 scans of 100 ms end at 3900 ms: 2^-zoom * 550 / 200 must reach it.
    let zoom: f64 = save
        .lines()
        .find_map(|l| l.strip_prefix('*'))
        .and_then(|l| l.split(' ').next())
        .and_then(|z| z.parse().ok())
        .expect("a zoom line");
    let shown = 2f64.powf(-zoom) * 550.0 / 200.0;
    assert!(
        (3900.0..4500.0).contains(&shown),
        "zoom {zoom} shows {shown} ms"
    );
}

/// An integer lane of the plot has ticks at whole numbers only and each
/// change's value written beside its step (room allowing): `n` going 3, 6
/// and `w` going 137, 274 show those values (no tick falls on them), and `k`
/// going 0 to 1 has no tick at 0.5.
#[test]
fn plot_integer_lanes_have_whole_ticks_and_labelled_changes() {
    let src = file(
        "count.il",
        "PROGRAM Count\nVAR go : BOOL; n : INT; w : UINT; k : INT; END_VAR\n\
         LD go\nJMPCN done\nLD n\nADD 3\nST n\nLD w\nADD 137\nST w\nLD 1\nST k\ndone:\nEND_PROGRAM\n",
    );
    let svg = dir().join("count.svg");
    let out = ilc(&[
        "run",
        &src,
        "--cycles",
        "12",
        "--step",
        "1s",
        "--set",
        "go=TRUE@4",
        "--set",
        "go=FALSE@6",
        "--watch",
        "n,w,k",
        "--plot",
        svg.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let svg = std::fs::read_to_string(&svg).unwrap();
    let texts: Vec<&str> = svg
        .split("<text")
        .skip(1)
        .filter_map(|t| t.split_once('>').and_then(|(_, r)| r.split_once("</text>")))
        .map(|(t, _)| t.trim())
        .collect();
    for want in ["3", "6", "137", "274"] {
        assert!(texts.contains(&want), "no label {want}: {texts:?}");
    }
    assert!(
        !texts
            .iter()
            .any(|t| t.contains('.') && t.parse::<f64>().is_ok()),
        "a tick between whole numbers: {texts:?}"
    );
}
