//! The Modbus TCP server: rmodbus parses requests and builds responses; this
//! module frames them on the socket and reads and writes the [`SharedImage`].
//!
//! Each client has a thread of its own and the scan thread only ever takes the
//! image's lock for a copy, so a client that connects and says nothing, sends
//! half a frame or stops reading its responses costs its own thread and
//! nothing else (and is dropped after the timeouts of [`ServerOptions`]).

use std::io::{self, ErrorKind as IoKind, Read, Write as _};
use std::net::{SocketAddr, TcpListener, TcpStream};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use il_std::{Area, ProcessImage};
use rmodbus::server::{ModbusFrame, Read as MbRead, Write as MbWrite};
use rmodbus::{ErrorKind, ModbusProto, consts::ModbusFunction};

use super::{Table, bit_place, register_place};
use crate::SharedImage;

/// How the server treats its clients.
#[derive(Clone, Debug)]
pub struct ServerOptions {
    /// Clients served at once; more are accepted and closed at once.
    pub max_clients: usize,
    /// A client silent this long between requests is disconnected.
    pub idle_timeout: Duration,
    /// A request (or a response write) must complete within this once begun.
    pub frame_timeout: Duration,
}

impl Default for ServerOptions {
    fn default() -> Self {
        ServerOptions {
            max_clients: 16,
            idle_timeout: Duration::from_secs(60),
            frame_timeout: Duration::from_secs(2),
        }
    }
}

/// A running Modbus TCP server; stops when dropped.
pub struct Server {
    addr: SocketAddr,
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

/// How often blocked threads look at the stop flag.
const POLL: Duration = Duration::from_millis(50);

impl Server {
    /// Listens on `listen` (port 0: any free port, see [`Server::local_addr`]).
    pub fn start(
        listen: SocketAddr,
        image: Arc<SharedImage>,
        opts: ServerOptions,
    ) -> io::Result<Server> {
        let listener = TcpListener::bind(listen)?;
        let addr = listener.local_addr()?;
        // Non-blocking accept, polled: the thread can see the stop flag.
        listener.set_nonblocking(true)?;
        let stop = Arc::new(AtomicBool::new(false));
        let flag = stop.clone();
        let thread = std::thread::Builder::new()
            .name("modbus-accept".into())
            .spawn(move || accept_loop(listener, image, opts, flag))?;
        Ok(Server {
            addr,
            stop,
            thread: Some(thread),
        })
    }

    /// The address it listens on.
    pub fn local_addr(&self) -> SocketAddr {
        self.addr
    }

    /// Stops accepting and closes every client (within 50 ms).
    pub fn stop(&mut self) {
        self.stop.store(true, Ordering::SeqCst);
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        self.stop();
    }
}

fn accept_loop(
    listener: TcpListener,
    image: Arc<SharedImage>,
    opts: ServerOptions,
    stop: Arc<AtomicBool>,
) {
    let active = Arc::new(AtomicUsize::new(0));
    let mut clients: Vec<JoinHandle<()>> = Vec::new();
    while !stop.load(Ordering::SeqCst) {
        clients.retain(|c| !c.is_finished());
        match listener.accept() {
            Ok((stream, _)) => {
                if active.load(Ordering::SeqCst) >= opts.max_clients {
                    drop(stream);
                    continue;
                }
                active.fetch_add(1, Ordering::SeqCst);
                let (image, opts, stop, done) =
                    (image.clone(), opts.clone(), stop.clone(), active.clone());
                let spawned = std::thread::Builder::new()
                    .name("modbus-client".into())
                    .spawn(move || {
                        let _ = serve(stream, &image, &opts, &stop);
                        done.fetch_sub(1, Ordering::SeqCst);
                    });
                match spawned {
                    Ok(h) => clients.push(h),
                    Err(_) => {
                        active.fetch_sub(1, Ordering::SeqCst);
                    }
                }
            }
            Err(e) if e.kind() == IoKind::WouldBlock => std::thread::sleep(POLL / 5),
            // A failed accept (out of descriptors, a reset before accept) is
            // that connection's problem; keep listening.
            Err(_) => std::thread::sleep(POLL),
        }
    }
    for c in clients {
        let _ = c.join();
    }
}

fn serve(
    mut stream: TcpStream,
    image: &SharedImage,
    opts: &ServerOptions,
    stop: &AtomicBool,
) -> io::Result<()> {
    stream.set_nonblocking(false)?;
    stream.set_nodelay(true)?;
    stream.set_read_timeout(Some(POLL))?;
    stream.set_write_timeout(Some(opts.frame_timeout))?;
    loop {
        let Some(req) = read_frame(&mut stream, opts, stop)? else {
            return Ok(());
        };
        match respond(&req, image) {
            Some(resp) => stream.write_all(&resp)?,
            // Not Modbus TCP any more: framing is lost, close.
            None => return Ok(()),
        }
    }
}

/// One request: the 7-byte MBAP header and the PDU its length announces.
/// `None` when the client closed, went idle or the runtime stops.
fn read_frame(
    s: &mut TcpStream,
    opts: &ServerOptions,
    stop: &AtomicBool,
) -> io::Result<Option<Vec<u8>>> {
    let mut head = [0u8; 7];
    let idle = Instant::now() + opts.idle_timeout;
    // The first byte may be long in coming; the rest of the frame may not.
    if !read_full(s, &mut head[..1], idle, stop)? {
        return Ok(None);
    }
    let deadline = Instant::now() + opts.frame_timeout;
    if !read_full(s, &mut head[1..], deadline, stop)? {
        return Ok(None);
    }
    let len = usize::from(u16::from_be_bytes([head[4], head[5]]));
    // The length counts the unit byte and the PDU (at most 253 bytes).
    if head[2..4] != [0, 0] || !(2..=254).contains(&len) {
        return Ok(None);
    }
    let mut frame = head.to_vec();
    frame.resize(6 + len, 0);
    if !read_full(s, &mut frame[7..], deadline, stop)? {
        return Ok(None);
    }
    Ok(Some(frame))
}

/// Fills `buf`; `false` at end of stream, past `deadline`, or on stop.
fn read_full(
    s: &mut TcpStream,
    buf: &mut [u8],
    deadline: Instant,
    stop: &AtomicBool,
) -> io::Result<bool> {
    let mut at = 0;
    while at < buf.len() {
        if stop.load(Ordering::SeqCst) || Instant::now() > deadline {
            return Ok(false);
        }
        match s.read(&mut buf[at..]) {
            Ok(0) => return Ok(false),
            Ok(n) => at += n,
            Err(e) if matches!(e.kind(), IoKind::WouldBlock | IoKind::TimedOut) => {}
            Err(e) if e.kind() == IoKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
    Ok(true)
}

/// The response to one framed request, or `None` when it is not a Modbus TCP
/// frame at all (the connection is then closed).
pub(crate) fn respond(req: &[u8], image: &SharedImage) -> Option<Vec<u8>> {
    // rmodbus reads a request at fixed offsets (a bulk write's data runs to
    // the byte count it announces): give it a zero-padded copy longer than any
    // frame, so that no announced length reaches past the buffer, and check
    // below that what was announced was actually sent.
    let mut buf = [0u8; 300];
    buf.get_mut(..req.len())?.copy_from_slice(req);
    let unit = *req.get(6)?;
    let f = *req.get(7)?;
    // Answered here, before rmodbus: an unknown function whatever its length
    // (rmodbus wants 6 bytes after the header, and computes `f + 0x80`,
    // which overflows for f >= 0x80), and a known one cut short.
    let Ok(func) = ModbusFunction::try_from(f) else {
        return Some(exception(req, f, 1));
    };
    if !complete(req, func) {
        return Some(exception(req, f, 3));
    }
    let mut response = Vec::new();
    // Over TCP the unit id addresses a gateway's device, not us: answer any,
    // and never treat unit 0 as a broadcast (no reply) as a serial line would.
    let mut frame =
        ModbusFrame::new(unit, &buf, ModbusProto::TcpUdp, &mut response).with_broadcast_units(&[]);
    frame.parse().ok()?;
    if frame.processing_required {
        let table = match frame.func {
            ModbusFunction::GetCoils | ModbusFunction::SetCoil | ModbusFunction::SetCoilsBulk => {
                Table::Coils
            }
            ModbusFunction::GetDiscretes => Table::DiscreteInputs,
            ModbusFunction::GetInputs => Table::InputRegisters,
            _ => Table::HoldingRegisters,
        };
        if frame.readonly {
            let r = frame.get_external_read().ok()?;
            let result = image.read(|io| read(table, r, io));
            frame.process_external_read(result).ok()?;
        } else {
            let w = frame.get_external_write();
            let result = match w {
                Ok(w) => write(table, w, image),
                Err(e) => Err(e),
            };
            frame.process_external_write(result).ok()?;
        }
    }
    if !frame.response_required {
        return None;
    }
    frame.finalize_response().ok()?;
    Some(response)
}

/// An exception response: the request's transaction id, its unit, the
/// function with the high bit set, the code.
fn exception(req: &[u8], f: u8, code: u8) -> Vec<u8> {
    let mut r = req[..2].to_vec();
    r.extend_from_slice(&[0, 0, 0, 3, req[6], f | 0x80, code]);
    r
}

/// Whether the request holds all the bytes its function reads: the address
/// and count or value (4 bytes after the function code), and for a bulk write
/// exactly the data bytes its byte count announces, which must also match its
/// count.
fn complete(req: &[u8], f: ModbusFunction) -> bool {
    // MBAP (7) + function (1) + address (2) + count or value (2).
    if req.len() < 12 {
        return false;
    }
    let count = usize::from(u16::from_be_bytes([req[10], req[11]]));
    let per = match f {
        ModbusFunction::SetCoilsBulk => count.div_ceil(8),
        ModbusFunction::SetHoldingsBulk => count * 2,
        _ => return req.len() == 12,
    };
    req.len() >= 13 && usize::from(req[12]) == per && req.len() == 13 + per && count > 0
}

fn read(table: Table, r: MbRead<'_>, io: &ProcessImage) -> Result<(), ErrorKind> {
    match r {
        MbRead::Bits(b) => {
            for i in 0..b.count {
                let a = b
                    .address
                    .checked_add(i)
                    .ok_or(ErrorKind::IllegalDataAddress)?;
                let (area, byte, bit) = bit_place(table, a).ok_or(ErrorKind::IllegalDataAddress)?;
                let slot = b
                    .buf
                    .get_mut(usize::from(i / 8))
                    .ok_or(ErrorKind::IllegalDataValue)?;
                if io.bit(area, byte, bit) {
                    *slot |= 1 << (i % 8);
                }
            }
            Ok(())
        }
        MbRead::Words(w) => {
            for i in 0..w.count {
                let a = w
                    .address
                    .checked_add(i)
                    .ok_or(ErrorKind::IllegalDataAddress)?;
                let (area, byte) = register_place(table, a).ok_or(ErrorKind::IllegalDataAddress)?;
                let at = usize::from(i) * 2;
                let slot = w
                    .buf
                    .get_mut(at..at + 2)
                    .ok_or(ErrorKind::IllegalDataValue)?;
                slot.copy_from_slice(&io.word(area, byte).to_be_bytes());
            }
            Ok(())
        }
    }
}

fn write(table: Table, w: MbWrite<'_>, image: &SharedImage) -> Result<(), ErrorKind> {
    // Every address is checked before anything is queued: a request is
    // applied whole or not at all.
    match w {
        MbWrite::Bits(b) => {
            let mut bits: Vec<(Area, usize, u8, bool)> = Vec::with_capacity(b.count.into());
            for i in 0..b.count {
                let a = b
                    .address
                    .checked_add(i)
                    .ok_or(ErrorKind::IllegalDataAddress)?;
                let (area, byte, bit) = bit_place(table, a).ok_or(ErrorKind::IllegalDataAddress)?;
                let v = b
                    .data
                    .get(usize::from(i / 8))
                    .ok_or(ErrorKind::IllegalDataValue)?;
                bits.push((area, byte, bit, v >> (i % 8) & 1 == 1));
            }
            image
                .write(Box::new(move |io: &mut ProcessImage| {
                    for &(area, byte, bit, v) in &bits {
                        io.set_bit(area, byte, bit, v);
                    }
                }))
                .map_err(|_| ErrorKind::SlaveDeviceBusy)
        }
        MbWrite::Words(ws) => {
            let mut words: Vec<(Area, usize, u16)> = Vec::with_capacity(ws.count.into());
            for i in 0..ws.count {
                let a = ws
                    .address
                    .checked_add(i)
                    .ok_or(ErrorKind::IllegalDataAddress)?;
                let (area, byte) = register_place(table, a).ok_or(ErrorKind::IllegalDataAddress)?;
                let at = usize::from(i) * 2;
                let v = ws.data.get(at..at + 2).ok_or(ErrorKind::IllegalDataValue)?;
                words.push((area, byte, u16::from_be_bytes([v[0], v[1]])));
            }
            image
                .write(Box::new(move |io: &mut ProcessImage| {
                    for &(area, byte, v) in &words {
                        io.set_word(area, byte, v);
                    }
                }))
                .map_err(|_| ErrorKind::SlaveDeviceBusy)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image() -> SharedImage {
        SharedImage::new(&ProcessImage::default())
    }

    /// An MBAP frame around `pdu` (unit 1, transaction 7).
    fn frame(pdu: &[u8]) -> Vec<u8> {
        let mut f = vec![0, 7, 0, 0];
        f.extend_from_slice(&((pdu.len() + 1) as u16).to_be_bytes());
        f.push(1);
        f.extend_from_slice(pdu);
        f
    }

    #[test]
    fn exceptions_for_unknown_functions_bad_addresses_and_lying_lengths() {
        let img = image();
        let exc = |pdu: &[u8]| {
            let r = respond(&frame(pdu), &img).expect("a response");
            (r[7], r[8])
        };
        assert_eq!(exc(&[0x2B, 0, 0, 0, 1]), (0xAB, 1));
        // Unknown functions of any length, the high bit set or not.
        assert_eq!(exc(&[0x07]), (0x87, 1));
        assert_eq!(exc(&[0x81, 0, 0, 0, 1]), (0x81, 1));
        assert_eq!(exc(&[0xFF]), (0xFF, 1));
        // A known function cut short, or with bytes after its fields.
        assert_eq!(exc(&[0x03, 0, 0]), (0x83, 3));
        assert_eq!(exc(&[0x03, 0, 0, 0, 1, 9]), (0x83, 3));
        assert_eq!(exc(&[0x01, 0x08, 0x00, 0, 1]), (0x81, 2)); // coil 2048
        assert_eq!(exc(&[0x03, 0, 200, 0, 1]), (0x83, 2)); // the gap after %QW127
        assert_eq!(exc(&[0x03, 0, 127, 0, 2]), (0x83, 2)); // runs into the gap
        assert_eq!(exc(&[0x03, 0xFF, 0xFF, 0, 2]), (0x83, 2)); // wraps past 65535
        // Announces 4 data bytes, sends 2: a lie rmodbus would read past.
        assert_eq!(exc(&[0x10, 0x04, 0x00, 0, 2, 4, 0, 1]), (0x90, 3));
        // Announces 246 bytes with an empty frame after it.
        assert_eq!(exc(&[0x0F, 0, 0, 0x07, 0xB0, 246]), (0x8F, 3));
        // Nothing was written by the refused requests.
        assert_eq!(img.read(|io| io.clone()), ProcessImage::default());
        // Too short to be Modbus TCP: no answer, the connection closes.
        assert_eq!(respond(&[0, 1, 0, 0, 0], &img), None);
    }

    #[test]
    fn random_requests_never_panic_and_known_functions_always_get_an_answer() {
        let img = image();
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        for _ in 0..50_000 {
            let len = (next() % 20) as usize + if next() % 8 == 0 { 240 } else { 1 };
            let mut pdu: Vec<u8> = (0..len).map(|_| next() as u8).collect();
            // Mostly the served functions, with addresses near the table's edges.
            if next() % 4 != 0 {
                pdu[0] = [1, 2, 3, 4, 5, 6, 15, 16][(next() % 8) as usize];
            }
            let r = respond(&frame(&pdu), &img);
            if let Some(r) = &r {
                assert_eq!(&r[..2], &[0, 7], "transaction id echoed");
                assert_eq!(r[7] & 0x7F, pdu[0] & 0x7F);
            }
            assert!(r.is_some(), "no answer to {pdu:02x?}");
        }
    }

    #[test]
    fn writes_then_reads_back() {
        let img = image();
        let ok = respond(&frame(&[0x10, 0x04, 0x00, 0, 2, 4, 0, 5, 0, 6]), &img).unwrap();
        assert_eq!(ok[7], 0x10);
        let r = respond(&frame(&[0x03, 0x04, 0x00, 0, 2]), &img).unwrap();
        assert_eq!(&r[7..], &[0x03, 4, 0, 5, 0, 6]);
        respond(&frame(&[0x05, 0, 9, 0xFF, 0]), &img).unwrap();
        assert!(img.get(il_std::addr::qx(1, 1)));
        // Coil n is bit n % 8 of data byte n / 8, least significant first.
        respond(&frame(&[0x0F, 0, 0, 0, 3, 1, 0b101]), &img).unwrap();
        let r = respond(&frame(&[0x01, 0, 0, 0, 10]), &img).unwrap();
        assert_eq!(&r[7..], &[0x01, 2, 0b0000_0101, 0b0000_0010]);
        assert!(img.get(il_std::addr::qx(0, 2)) && !img.get(il_std::addr::qx(0, 1)));
        // A single-coil value other than FF00/0000 is exception 3.
        let r = respond(&frame(&[0x05, 0, 9, 0x12, 0x34]), &img).unwrap();
        assert_eq!((r[7], r[8]), (0x85, 3));
    }
}
