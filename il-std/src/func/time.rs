//! Time and date functions: ADD_TIME SUB_TIME MUL_TIME DIV_TIME, ADD_TOD_TIME ADD_DT_TIME
//! SUB_TOD_TIME SUB_DT_TIME SUB_DATE_DATE SUB_TOD_TOD SUB_DT_DT CONCAT_DATE_TOD.
//!
//! All arithmetic wraps at the `i64` nanosecond range except where said otherwise; a
//! `TIME_OF_DAY` result is taken modulo 24 h.

use crate::num::AnyNum;
use crate::time::{DATE, DT, NS_PER_DAY, TIME, TOD};

/// `ADD_TIME` (also `ADD` on `TIME`): `IN1 + IN2`, wrapping.
pub fn ADD_TIME(IN1: TIME, IN2: TIME) -> TIME {
    IN1.wrapping_add(IN2)
}

/// `SUB_TIME` (also `SUB` on `TIME`): `IN1 - IN2`, wrapping.
pub fn SUB_TIME(IN1: TIME, IN2: TIME) -> TIME {
    IN1.wrapping_sub(IN2)
}

/// `MUL_TIME` (also `MUL` of `TIME` by `ANY_NUM`): integers multiply wrapping; reals multiply
/// rounded to the nearest nanosecond, saturating (NaN gives `T#0s`).
pub fn MUL_TIME<N: AnyNum>(IN1: TIME, IN2: N) -> TIME {
    match IN2.as_i64_exact() {
        Some(k) => IN1.mul_int(k),
        None => IN1.mul_real(IN2.to_f64()),
    }
}

/// `DIV_TIME` (also `DIV` of `TIME` by `ANY_NUM`): integers divide truncating toward zero and
/// division by zero gives `T#0s` (see [`div_time_checked`]); reals divide rounded to the
/// nearest nanosecond, saturating (`/ 0.0` gives the extreme `TIME`, NaN gives `T#0s`).
pub fn DIV_TIME<N: AnyNum>(IN1: TIME, IN2: N) -> TIME {
    div_time_checked(IN1, IN2).0
}

/// [`DIV_TIME`] plus `true` for an integer division by zero.
pub fn div_time_checked<N: AnyNum>(IN1: TIME, IN2: N) -> (TIME, bool) {
    match IN2.as_i64_exact() {
        Some(k) => (IN1.div_int(k), k == 0),
        None => (IN1.div_real(IN2.to_f64()), false),
    }
}

/// `ADD_TOD_TIME`: time of day plus a duration, modulo 24 h.
pub fn ADD_TOD_TIME(IN1: TOD, IN2: TIME) -> TOD {
    TOD(IN1.0.wrapping_add(IN2.0).rem_euclid(NS_PER_DAY))
}

/// `SUB_TOD_TIME`: time of day minus a duration, modulo 24 h.
pub fn SUB_TOD_TIME(IN1: TOD, IN2: TIME) -> TOD {
    TOD(IN1.0.wrapping_sub(IN2.0).rem_euclid(NS_PER_DAY))
}

/// `ADD_DT_TIME`: date and time plus a duration (wrapping).
pub fn ADD_DT_TIME(IN1: DT, IN2: TIME) -> DT {
    DT(IN1.0.wrapping_add(IN2.0))
}

/// `SUB_DT_TIME`: date and time minus a duration (wrapping).
pub fn SUB_DT_TIME(IN1: DT, IN2: TIME) -> DT {
    DT(IN1.0.wrapping_sub(IN2.0))
}

/// `SUB_DATE_DATE`: the duration between two dates (`IN1 - IN2`, whole days; wrapping).
pub fn SUB_DATE_DATE(IN1: DATE, IN2: DATE) -> TIME {
    TIME(IN1.0.wrapping_sub(IN2.0).wrapping_mul(NS_PER_DAY))
}

/// `SUB_TOD_TOD`: the duration between two times of day (`IN1 - IN2`, may be negative).
pub fn SUB_TOD_TOD(IN1: TOD, IN2: TOD) -> TIME {
    TIME(IN1.0.wrapping_sub(IN2.0))
}

/// `SUB_DT_DT`: the duration between two dates and times (`IN1 - IN2`, wrapping).
pub fn SUB_DT_DT(IN1: DT, IN2: DT) -> TIME {
    TIME(IN1.0.wrapping_sub(IN2.0))
}

/// `CONCAT_DATE_TOD`: the date `IN1` at the time of day `IN2`.
pub fn CONCAT_DATE_TOD(IN1: DATE, IN2: TOD) -> DT {
    DT::from_date_tod(IN1, IN2)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tod(h: u32, m: u32, s: u32) -> TOD {
        TOD::from_hms(h, m, s).unwrap()
    }

    #[test]
    fn durations() {
        let s = TIME::from_secs;
        assert_eq!(ADD_TIME(s(1), s(2)), s(3));
        assert_eq!(ADD_TIME(TIME::MAX, TIME(1)), TIME::MIN);
        assert_eq!(SUB_TIME(s(1), s(2)), s(-1));
        assert_eq!(MUL_TIME(s(2), 3i16), s(6));
        assert_eq!(MUL_TIME(s(2), 1.5f32), s(3));
        assert_eq!(MUL_TIME(s(2), f64::NAN), TIME(0));
        assert_eq!(MUL_TIME(TIME::MAX, 2u8), TIME(-2));
        assert_eq!(MUL_TIME(s(1), 1e300f64), TIME::MAX);
        assert_eq!(DIV_TIME(s(3), 2i32), TIME::from_ms(1500));
        assert_eq!(DIV_TIME(s(3), 0i32), TIME(0));
        assert_eq!(div_time_checked(s(3), 0u16), (TIME(0), true));
        assert_eq!(div_time_checked(s(3), 0.0f64), (TIME::MAX, false));
        assert_eq!(DIV_TIME(s(1), 3.0f64), TIME(333_333_333));
        assert_eq!(DIV_TIME(TIME::MIN, -1i64), TIME::MIN);
    }

    #[test]
    fn dates() {
        assert_eq!(
            ADD_TOD_TIME(tod(23, 0, 0), TIME::from_secs(7200)),
            tod(1, 0, 0)
        );
        assert_eq!(
            SUB_TOD_TIME(tod(1, 0, 0), TIME::from_secs(7200)),
            tod(23, 0, 0)
        );
        assert_eq!(
            ADD_TOD_TIME(tod(0, 0, 0), TIME::MIN),
            TOD(TIME::MIN.0.rem_euclid(NS_PER_DAY))
        );
        let d = DATE::from_ymd(2001, 4, 9).unwrap();
        let dt = CONCAT_DATE_TOD(d, tod(11, 36, 15));
        assert_eq!(dt, DT::from_parts(2001, 4, 9, 11, 36, 15, 0).unwrap());
        assert_eq!(
            ADD_DT_TIME(dt, TIME::from_secs(13 * 3600)),
            DT::from_parts(2001, 4, 10, 0, 36, 15, 0).unwrap()
        );
        assert_eq!(
            SUB_DT_TIME(dt, TIME::from_secs(12 * 3600)),
            DT::from_parts(2001, 4, 8, 23, 36, 15, 0).unwrap()
        );
        assert_eq!(
            SUB_DATE_DATE(DATE::from_ymd(2001, 4, 10).unwrap(), d),
            TIME::from_secs(86_400)
        );
        assert_eq!(
            SUB_DATE_DATE(d, DATE::from_ymd(2001, 4, 10).unwrap()),
            TIME::from_secs(-86_400)
        );
        assert_eq!(
            SUB_TOD_TOD(tod(1, 0, 0), tod(2, 0, 0)),
            TIME::from_secs(-3600)
        );
        assert_eq!(SUB_DT_DT(ADD_DT_TIME(dt, TIME(5)), dt), TIME(5));
        assert_eq!(
            SUB_DATE_DATE(DATE(i64::MAX), DATE(i64::MIN)),
            TIME((-1i64).wrapping_mul(NS_PER_DAY))
        );
    }
}
