//! The date and time `[DATE]` and `[TIME]` print when neither the job nor
//! `--set` gives them, in UTC, from the Unix time the caller passes as
//! [`RunOptions::now`](crate::RunOptions::now): the date in the long form
//! VCarve writes (`Tuesday, November 15, 2011`, docs/vectric.md), the time
//! as `HH:MM`.
//! The runtime never reads the clock: the command line does (now, or the
//! time `SOURCE_DATE_EPOCH` names, the reproducible-builds convention).

const WEEKDAYS: [&str; 7] = ["Sunday", "Monday", "Tuesday", "Wednesday", "Thursday", "Friday", "Saturday"];

const MONTHS: [&str; 12] = [
    "January",
    "February",
    "March",
    "April",
    "May",
    "June",
    "July",
    "August",
    "September",
    "October",
    "November",
    "December",
];

/// Date and time of a Unix time, in UTC.
pub fn format_utc(seconds: i64) -> (String, String) {
    let days = seconds.div_euclid(86_400);
    let secs = seconds.rem_euclid(86_400);
    let (y, m, d) = civil_from_days(days);
    // 1970-01-01 was a Thursday.
    let weekday = WEEKDAYS[(days + 4).rem_euclid(7) as usize];
    let month = MONTHS[(m - 1) as usize];
    (format!("{weekday}, {month} {d}, {y}"), format!("{:02}:{:02}", secs / 3600, secs % 3600 / 60))
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
