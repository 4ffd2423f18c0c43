//! The example's configuration served over Modbus TCP to the crate's own client.

use std::io::Write;
use std::net::TcpStream;
use std::time::Duration;

use il_runtime::client::{Client, ClientError};
use il_runtime::{Options, RetainLoad, Runtime};

use crate::common::{eventually, hmi::Hmi, modbus_opts, scans, temp_dir};

fn client(rt: &Runtime) -> Client {
    Client::connect(rt.modbus_addr().expect("modbus on"), Duration::from_secs(5)).expect("connect")
}

/// Presses a button (a coil) until the runtime has scanned it, then releases it.
fn press(rt: &Runtime, c: &mut Client, coil: u16) {
    c.write_coil(coil, true).unwrap();
    scans(rt, 2);
    c.write_coil(coil, false).unwrap();
    scans(rt, 2);
}

fn starts(c: &mut Client) -> u16 {
    c.read_holding(1024, 1).unwrap()[0]
}

#[test]
fn an_hmi_starts_and_stops_the_motor_and_the_count_survives_a_restart() {
    let dir = temp_dir("hmi");
    let opts = Options {
        retain: Some(dir.join("motor.retain")),
        ..modbus_opts()
    };
    let rt = Runtime::start(Hmi::default(), opts.clone()).unwrap();
    assert!(matches!(rt.retain_load(), RetainLoad::Missing));
    let mut c = client(&rt);
    assert_eq!(c.read_coils(0, 3).unwrap(), [false, false, false]);
    press(&rt, &mut c, 1); // start
    assert_eq!(c.read_coils(0, 1).unwrap(), [true], "run is sealed in");
    assert_eq!(starts(&mut c), 1);
    press(&rt, &mut c, 2); // stop
    assert_eq!(c.read_coils(0, 1).unwrap(), [false]);
    press(&rt, &mut c, 1);
    assert_eq!(starts(&mut c), 2);
    let report = rt.stop().unwrap();
    assert!(report.retain_saves >= 1, "saved on stop");
    assert_eq!(report.retain_error, None);
    assert!(report.task("Main").unwrap().scans >= 8);

    // A new runtime: a warm start.
    let rt = Runtime::start(Hmi::default(), opts).unwrap();
    assert!(
        matches!(rt.retain_load(), RetainLoad::Restored),
        "{:?}",
        rt.retain_load()
    );
    let mut c = client(&rt);
    assert_eq!(starts(&mut c), 2, "the retained count");
    assert_eq!(c.read_coils(0, 1).unwrap(), [false], "run is not RETAIN");
    press(&rt, &mut c, 1);
    assert_eq!(starts(&mut c), 3);
    rt.stop().unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_requests_get_exception_responses_and_the_connection_stays_usable() {
    let rt = Runtime::start(Hmi::default(), modbus_opts()).unwrap();
    let mut c = client(&rt);
    let code = |r: Result<Vec<u16>, ClientError>| match r {
        Err(ClientError::Exception(code)) => code,
        other => panic!("expected an exception, got {other:?}"),
    };
    // Function 0x2B (encapsulated interface transport) is not served.
    let resp = c.raw(&[0, 9, 0, 0, 0, 6, 1, 0x2B, 0, 0, 0, 1]).unwrap();
    assert_eq!(&resp[..2], &[0, 9], "the transaction id is echoed");
    assert_eq!(&resp[7..], &[0xAB, 1], "illegal function");
    assert!(matches!(
        c.read_coils(2047, 2),
        Err(ClientError::Exception(2))
    ));
    assert_eq!(code(c.read_holding(128, 1)), 2, "between %QW and %MW");
    assert_eq!(code(c.read_holding(1536, 1)), 2, "after %MW");
    assert_eq!(code(c.read_input_registers(128, 1)), 2);
    assert!(matches!(
        c.write_holding(4608, &[1]),
        Err(ClientError::Exception(2))
    ));
    assert!(matches!(
        c.write_holding(1535, &[1, 2]),
        Err(ClientError::Exception(2))
    ));
    assert_eq!(code(c.read_holding(0, 126)), 3, "more than 125 registers");
    // Still served, and nothing above was written.
    assert_eq!(c.read_holding(1535, 1).unwrap(), [0]);
    c.write_holding(2048, &[0x0001, 0x0002]).unwrap();
    assert_eq!(
        c.read_holding(1024, 2).unwrap(),
        [0x0002, 0x0001],
        "%MD0 is %MW0..1"
    );
    rt.stop().unwrap();
}

#[test]
fn a_hung_client_does_not_stall_the_scan_or_other_clients() {
    let mut opts = modbus_opts();
    // So that the server gives up on the deaf client below within the test.
    opts.modbus_options.frame_timeout = Duration::from_millis(200);
    let rt = Runtime::start(Hmi::default(), opts).unwrap();
    let addr = rt.modbus_addr().unwrap();
    // One connects and says nothing; one sends half a header and stops.
    let _silent = TcpStream::connect(addr).unwrap();
    let mut half = TcpStream::connect(addr).unwrap();
    half.write_all(&[0, 1, 0]).unwrap();
    // One sends requests and never reads the answers (1.3 MB of them, more
    // than the socket buffers hold): the server's write to it times out.
    let mut deaf = TcpStream::connect(addr).unwrap();
    deaf.set_write_timeout(Some(Duration::from_millis(50)))
        .unwrap();
    let read = [0u8, 1, 0, 0, 0, 6, 1, 3, 0, 0, 0, 125];
    for _ in 0..5000 {
        if deaf.write_all(&read).is_err() {
            break;
        }
    }
    scans(&rt, 20);
    let mut c = client(&rt);
    c.write_coil(1, true).unwrap();
    eventually("run", || c.read_coils(0, 1).unwrap()[0].then_some(()));
    let report = rt.stop().unwrap();
    assert!(report.scans >= 20, "{report:?}");
}

#[test]
fn clients_past_the_limit_and_idle_ones_are_disconnected() {
    let mut opts = modbus_opts();
    opts.modbus_options.max_clients = 1;
    opts.modbus_options.idle_timeout = Duration::from_millis(300);
    let rt = Runtime::start(Hmi::default(), opts).unwrap();
    let mut first = client(&rt);
    assert_eq!(first.read_coils(0, 1).unwrap(), [false]);
    // The second is accepted and closed at once: its request gets no answer.
    let mut second = client(&rt);
    assert!(matches!(second.read_coils(0, 1), Err(ClientError::Io(_))));
    // The first, silent past the idle timeout, is closed too.
    std::thread::sleep(Duration::from_millis(1200));
    assert!(matches!(first.read_coils(0, 1), Err(ClientError::Io(_))));
    // Which frees its place.
    let mut third = eventually("a free place", || {
        let mut c = client(&rt);
        c.read_coils(0, 1).is_ok().then_some(c)
    });
    assert_eq!(third.read_holding(1024, 1).unwrap(), [0]);
    rt.stop().unwrap();
}
