//! A small blocking Modbus TCP client (rmodbus builds and parses the frames):
//! what the tests and a simple HMI or test bench use to talk to the runtime.

use std::fmt;
use std::io::{self, Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::time::Duration;

use rmodbus::ErrorKind;
use rmodbus::client::ModbusRequest;

/// What went wrong with a request.
#[derive(Debug)]
pub enum ClientError {
    /// The connection failed or timed out.
    Io(io::Error),
    /// The server answered with a Modbus exception (its code: 1 illegal
    /// function, 2 illegal data address, 3 illegal data value ...).
    Exception(u8),
    /// The answer was not a Modbus TCP response to the request.
    Protocol(String),
}

impl fmt::Display for ClientError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ClientError::Io(e) => write!(f, "modbus connection: {e}"),
            ClientError::Exception(c) => write!(f, "modbus exception {c}"),
            ClientError::Protocol(m) => write!(f, "modbus protocol: {m}"),
        }
    }
}

impl std::error::Error for ClientError {}

impl From<io::Error> for ClientError {
    fn from(e: io::Error) -> Self {
        ClientError::Io(e)
    }
}

fn mb(e: ErrorKind) -> ClientError {
    if e.is_modbus_error() {
        // rmodbus folds the code into its ErrorKind; give the user the number.
        let code = match e {
            ErrorKind::IllegalFunction => 1,
            ErrorKind::IllegalDataAddress => 2,
            ErrorKind::IllegalDataValue => 3,
            ErrorKind::SlaveDeviceFailure => 4,
            ErrorKind::SlaveDeviceBusy => 6,
            _ => 0,
        };
        ClientError::Exception(code)
    } else {
        ClientError::Protocol(format!("{e:?}"))
    }
}

/// A connection to a Modbus TCP server.
pub struct Client {
    stream: TcpStream,
    tr_id: u16,
    unit: u8,
}

impl Client {
    /// Connects, with `timeout` for the connection and for each answer.
    pub fn connect(addr: SocketAddr, timeout: Duration) -> Result<Client, ClientError> {
        let stream = TcpStream::connect_timeout(&addr, timeout)?;
        stream.set_read_timeout(Some(timeout))?;
        stream.set_write_timeout(Some(timeout))?;
        stream.set_nodelay(true)?;
        Ok(Client {
            stream,
            tr_id: 0,
            unit: 1,
        })
    }

    fn request(&mut self) -> ModbusRequest {
        self.tr_id = self.tr_id.wrapping_add(1);
        ModbusRequest::new_tcp_udp(self.unit, self.tr_id)
    }

    /// Sends a whole frame as given and returns the response frame: for
    /// requests the typed methods do not make (unknown functions, say).
    pub fn raw(&mut self, frame: &[u8]) -> Result<Vec<u8>, ClientError> {
        self.stream.write_all(frame)?;
        let mut head = [0u8; 6];
        self.stream.read_exact(&mut head)?;
        let len = usize::from(u16::from_be_bytes([head[4], head[5]]));
        if !(2..=254).contains(&len) {
            return Err(ClientError::Protocol(format!("length {len}")));
        }
        let mut resp = head.to_vec();
        resp.resize(6 + len, 0);
        self.stream.read_exact(&mut resp[6..])?;
        Ok(resp)
    }

    fn exchange(&mut self, req: &ModbusRequest, frame: &[u8]) -> Result<Vec<u8>, ClientError> {
        let resp = self.raw(frame)?;
        req.parse_ok(&resp).map_err(mb)?;
        Ok(resp)
    }

    /// Reads `count` coils (`%QX`) from `addr`.
    pub fn read_coils(&mut self, addr: u16, count: u16) -> Result<Vec<bool>, ClientError> {
        let mut req = self.request();
        let mut frame = Vec::new();
        req.generate_get_coils(addr, count, &mut frame)
            .map_err(mb)?;
        self.bits(&req, &frame)
    }

    /// Reads `count` discrete inputs (`%IX`) from `addr`.
    pub fn read_discrete_inputs(
        &mut self,
        addr: u16,
        count: u16,
    ) -> Result<Vec<bool>, ClientError> {
        let mut req = self.request();
        let mut frame = Vec::new();
        req.generate_get_discretes(addr, count, &mut frame)
            .map_err(mb)?;
        self.bits(&req, &frame)
    }

    fn bits(&mut self, req: &ModbusRequest, frame: &[u8]) -> Result<Vec<bool>, ClientError> {
        let resp = self.exchange(req, frame)?;
        let mut out = Vec::new();
        req.parse_bool(&resp, &mut out).map_err(mb)?;
        Ok(out)
    }

    /// Reads `count` holding registers from `addr`.
    pub fn read_holding(&mut self, addr: u16, count: u16) -> Result<Vec<u16>, ClientError> {
        let mut req = self.request();
        let mut frame = Vec::new();
        req.generate_get_holdings(addr, count, &mut frame)
            .map_err(mb)?;
        self.words(&req, &frame)
    }

    /// Reads `count` input registers (`%IW`) from `addr`.
    pub fn read_input_registers(&mut self, addr: u16, count: u16) -> Result<Vec<u16>, ClientError> {
        let mut req = self.request();
        let mut frame = Vec::new();
        req.generate_get_inputs(addr, count, &mut frame)
            .map_err(mb)?;
        self.words(&req, &frame)
    }

    fn words(&mut self, req: &ModbusRequest, frame: &[u8]) -> Result<Vec<u16>, ClientError> {
        let resp = self.exchange(req, frame)?;
        // rmodbus's parse_u16 underflows on an empty data part: check first.
        if resp.len() < 9 + 2 * usize::from(req.count) {
            return Err(ClientError::Protocol("short register response".into()));
        }
        let mut out = Vec::new();
        req.parse_u16(&resp, &mut out).map_err(mb)?;
        Ok(out)
    }

    /// Writes one coil.
    pub fn write_coil(&mut self, addr: u16, v: bool) -> Result<(), ClientError> {
        let mut req = self.request();
        let mut frame = Vec::new();
        req.generate_set_coil(addr, u8::from(v), &mut frame)
            .map_err(mb)?;
        self.exchange(&req, &frame).map(drop)
    }

    /// Writes holding registers from `addr` (one: function 6, more: 16).
    pub fn write_holding(&mut self, addr: u16, values: &[u16]) -> Result<(), ClientError> {
        let mut req = self.request();
        let mut frame = Vec::new();
        match values {
            [v] => req.generate_set_holding(addr, *v, &mut frame),
            vs => req.generate_set_holdings_bulk(addr, vs, &mut frame),
        }
        .map_err(mb)?;
        self.exchange(&req, &frame).map(drop)
    }
}
