//! The scans of a debug session: `set` and `force` written between scans,
//! simulated time advanced by `cycleTime`, the session attached to the
//! machine as its hook for the scans and taken back for the end.

use serde_json::{Value, json};

use super::Session;
use crate::load::program_name;
use crate::run_target::Target;
use il_interp::Value as V;
use il_interp::il_std::Cycle;

/// Run the launched scans with `s` as the hook; the session back, after
/// `terminated` was sent (`None` only if the machine lost it).
pub fn drive<T: Target>(mut m: T, mut s: Session) -> Option<Session> {
    let Some(l) = s.launch.as_ref() else {
        return Some(s);
    };
    let (cycles, step, real_time) = (l.cycles, l.cycle_time, l.real_time);
    let mut sets: Vec<(u64, T::Place, V)> = Vec::new();
    for a in &l.sets {
        let r = m
            .lookup(&program_name(&a.var, s.m221))
            .and_then(|p| m.parse_for(&p, &a.value).map(|v| (a.cycle, p, v)));
        match r {
            Ok(x) => sets.push(x),
            Err(e) => {
                s.out
                    .output("stderr", &format!("set {}={}: {e}", a.var, a.value));
                return Some(end(s, 1));
            }
        }
    }
    // Forces named wrong are reported once and released.
    let mut forces = std::mem::take(&mut s.forces);
    let m221 = s.m221;
    forces.retain(|(p, v)| {
        match (m.lookup(&program_name(p, m221))).and_then(|pl| m.parse_for(&pl, v)) {
            Ok(_) => true,
            Err(e) => {
                s.out.output("stderr", &format!("force {p}={v}: {e}"));
                false
            }
        }
    });
    s.forces = forces;
    m.set_hook(Some(Box::new(s)));
    let mut ctx = Cycle::new();
    let mut k = 0u64;
    let mut code = 0;
    loop {
        k += 1;
        if cycles.is_some_and(|n| k > n) {
            break;
        }
        let Some(s) = m.hook_mut::<Session>() else {
            break;
        };
        s.scan = k;
        s.now = ctx.now();
        s.flow.clear();
        s.last = None;
        if s.attention() {
            s.drain();
        }
        if s.quit {
            break;
        }
        let forces = s.forces.clone();
        for (c, p, v) in &sets {
            if *c == k
                && let Err(e) = m.set_at(&mut ctx, p, v.clone())
            {
                report(&mut m, &format!("set: {e}"));
            }
        }
        force(&mut m, &mut ctx, &forces, m221);
        let started = std::time::Instant::now();
        let r = m.scan(&mut ctx);
        // The forces as they are now: one released while stopped is not written back.
        let forces = m
            .hook_mut::<Session>()
            .map(|s| s.forces.clone())
            .unwrap_or_default();
        force(&mut m, &mut ctx, &forces, m221);
        if let Err(e) = r {
            let Some(s) = m.hook_mut::<Session>() else {
                break;
            };
            if !s.quit {
                s.out.output("stderr", &format!("scan {k}: {e}"));
                code = 1;
            }
            break;
        }
        if real_time {
            pace(&mut m, started, step);
        }
        ctx.advance(step);
    }
    m.take_hook::<Session>().map(|s| end(*s, code))
}

/// `realTime`: wait out the rest of the cycle since `started`, answering
/// requests meanwhile (a stop inside the scan already took its time).
fn pace<T: Target>(m: &mut T, started: std::time::Instant, step: il_interp::il_std::TIME) {
    let cycle = std::time::Duration::from_nanos(step.0.max(0) as u64);
    while started.elapsed() < cycle {
        let Some(s) = m.hook_mut::<Session>() else {
            return;
        };
        if s.attention() {
            s.drain();
        }
        if s.quit {
            return;
        }
        let left = cycle.saturating_sub(started.elapsed());
        std::thread::sleep(left.min(std::time::Duration::from_millis(10)));
    }
}

fn report<T: Target>(m: &mut T, msg: &str) {
    if let Some(s) = m.hook_mut::<Session>() {
        s.out.output("stderr", msg);
    }
}

/// Write every forced value (checked before the first scan).
fn force<T: Target>(m: &mut T, ctx: &mut Cycle, forces: &[(String, String)], m221: bool) {
    for (p, v) in forces {
        let r = m
            .lookup(&program_name(p, m221))
            .and_then(|pl| m.parse_for(&pl, v).and_then(|x| m.set_at(ctx, &pl, x)));
        if let Err(e) = r {
            report(m, &format!("force {p}={v}: {e}"));
        }
    }
}

/// The run is over: `terminated` and `exited`.
fn end(mut s: Session, code: i64) -> Session {
    s.handles.clear();
    s.out.event("exited", json!({ "exitCode": code }));
    s.out.event("terminated", Value::Null);
    s
}
