//! A soft-PLC: the motor starter of `softplc.il` in a 10 ms task, served over
//! Modbus TCP, its start counter kept in a retain file.
//!
//! ```text
//! cargo run --release -p il-runtime --example softplc -- --modbus 127.0.0.1:5020 --retain motor.retain
//! ```
//!
//! Options: `--modbus ADDR` (default 127.0.0.1:5020), `--retain PATH`, `--fifo PRIO`
//! (ask for SCHED_FIFO; default 50), `--no-fifo`, `--watchdog MS`, `--seconds N`
//! (stop after N seconds; default: until Ctrl-C / SIGTERM), `--histogram` (print each
//! task's release latency histogram at the end: how BENCHMARKS.md's figures were taken).

use std::process::ExitCode;
use std::time::{Duration, Instant};

use il_runtime::{Options, RetainLoad, Runtime};

il_macros::il!(file = "examples/softplc.il", serde);
il_runtime::plc!(Hmi);

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("softplc: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<(), String> {
    let mut opts = Options {
        modbus: Some("127.0.0.1:5020".parse().map_err(|e| format!("{e}"))?),
        realtime: Some(50),
        signals: true,
        ..Default::default()
    };
    let mut seconds = None;
    let mut histogram = false;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = |what: &str| args.next().ok_or(format!("{a} needs {what}"));
        match a.as_str() {
            "--modbus" => {
                let v = value("an address")?;
                opts.modbus = Some(v.parse().map_err(|e| format!("--modbus {v}: {e}"))?);
            }
            "--retain" => opts.retain = Some(value("a path")?.into()),
            "--fifo" => opts.realtime = Some(number(&value("a priority")?)? as i32),
            "--no-fifo" => opts.realtime = None,
            "--watchdog" => {
                opts.watchdog = Some(Duration::from_millis(number(&value("milliseconds")?)?))
            }
            "--seconds" => seconds = Some(number(&value("a count")?)?),
            "--histogram" => histogram = true,
            _ => {
                return Err(format!(
                    "unknown argument {a} (see the example's documentation)"
                ));
            }
        }
    }
    let mut rt = Runtime::start(Hmi::default(), opts).map_err(|e| e.to_string())?;
    if let Some(a) = rt.modbus_addr() {
        println!("modbus tcp on {a}: coils 0 run, 1 start, 2 stop; holding register 1024 starts");
    }
    match rt.retain_load() {
        RetainLoad::Rejected(e) => println!("retain: {e}; starting from initial values"),
        l => println!("retain: {l:?}"),
    }
    println!("scheduler: {:?}", rt.realtime());
    let began = Instant::now();
    loop {
        if rt.wait_timeout(Duration::from_secs(1)) {
            break;
        }
        for t in rt.stats() {
            println!("{t}");
        }
        let (run, starts) = rt.image().read(|io| {
            (
                io.get(il_std::addr::qx(0, 0)),
                io.get(il_std::addr::mw(0).int()),
            )
        });
        println!("run {run}, starts {starts}");
        if seconds.is_some_and(|s| began.elapsed() >= Duration::from_secs(s)) {
            rt.request_stop();
        }
    }
    let report = rt.wait().map_err(|e| e.to_string())?;
    println!(
        "stopped after {} scans; retain files written: {}",
        report.scans, report.retain_saves
    );
    for t in &report.tasks {
        println!("{t}");
        if histogram {
            print_histogram(t);
        }
    }
    if let Some(e) = report.retain_error {
        return Err(format!("retain: {e}"));
    }
    Ok(())
}

/// The non-empty buckets of a task's release latency histogram, and percentiles.
fn print_histogram(t: &il_runtime::TaskStats) {
    let mut line = format!("{} release latency:", t.name);
    for (k, n) in t.latency_histogram.iter().enumerate() {
        if *n > 0 {
            let lo = if k == 0 { 0 } else { 1u64 << (k - 1) };
            line.push_str(&format!(" [{lo}, {}) µs: {n};", 1u64 << k));
        }
    }
    println!("{line}");
    let p = |q: f64| t.latency_percentile(q).unwrap_or_default().as_micros();
    println!(
        "{} latency under (bucket bound): p50 {} µs, p99 {} µs, p99.9 {} µs; max {} µs",
        t.name,
        p(50.0),
        p(99.0),
        p(99.9),
        t.max_latency.as_micros()
    );
}

fn number(s: &str) -> Result<u64, String> {
    s.parse().map_err(|e| format!("{s}: {e}"))
}
