//! The date and time `[DATE]` and `[TIME]` print when neither the job nor
//! `--set` gives them, as `YYYY-MM-DD` and `HH:MM` in UTC, from the Unix
//! time the caller passes as [`RunOptions::now`](crate::RunOptions::now).
//! The runtime never reads the clock: the command line does (now, or the
//! time `SOURCE_DATE_EPOCH` names, the reproducible-builds convention).

/// Date and time of a Unix time, in UTC.
pub fn format_utc(seconds: i64) -> (String, String) {
    let days = seconds.div_euclid(86_400);
    let secs = seconds.rem_euclid(86_400);
    let (y, m, d) = civil_from_days(days);
    (format!("{y:04}-{m:02}-{d:02}"), format!("{:02}:{:02}", secs / 3600, secs % 3600 / 60))
}

/// Gregorian date of a day count since 1970-01-01 (Howard Hinnant's algorithm).
fn civil_from_days(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_dates() {
        assert_eq!(format_utc(0), ("1970-01-01".into(), "00:00".into()));
        assert_eq!(format_utc(951_782_400), ("2000-02-29".into(), "00:00".into()));
        assert_eq!(format_utc(1_795_422_900), ("2026-11-23".into(), "08:35".into()));
    }
}
