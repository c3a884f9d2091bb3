//! Reading records back from the CL file. The CL reader turns some records
//! into events that do not keep every word `postp` needs: the placement of
//! `COOLNT/..,NOW|NEXT`, whether a `Tool` came from `LOADTL` or only from
//! `CUTTER`, and the unit of a `FEDRAT` (which makes no event at all). Every
//! event carries the byte span of its record, so this module reads the
//! record's text again, and the text between events for FEDRAT records.
//! Only small pieces are read, through a second handle on the file that
//! the source map's loader opens (`postp` opens no file itself).

use std::io::{Read, Seek, SeekFrom};
use std::path::Path;

use postc_ir::source::SourceReader;
use postc_ir::{SourceLoader, Span};

/// The most of a gap between two events scanned for FEDRAT records.
const MAX_GAP: usize = 4 << 20;

/// A record as written: its major word and arguments, upper case, with
/// continuation lines joined and comments removed.
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    pub word: String,
    pub args: Vec<String>,
}

impl Record {
    /// Whether an argument is this word.
    pub fn has(&self, word: &str) -> bool {
        self.args.iter().any(|a| a == word)
    }
}

/// A second handle on the CL file.
pub struct ClText {
    file: Option<SourceReader>,
    /// Everything before this offset has been scanned for FEDRAT.
    scanned: usize,
}

impl ClText {
    pub fn open(loader: &dyn SourceLoader, path: &Path) -> ClText {
        ClText { file: loader.open(path).ok(), scanned: 0 }
    }

    fn read(&mut self, start: usize, end: usize) -> String {
        let Some(file) = self.file.as_mut() else { return String::new() };
        let len = end.saturating_sub(start).min(MAX_GAP);
        let mut buf = vec![0; len];
        let start = end - len;
        if file.seek(SeekFrom::Start(start as u64)).is_err() {
            return String::new();
        }
        let n = file.read(&mut buf).unwrap_or(0);
        buf.truncate(n);
        String::from_utf8_lossy(&buf).into_owned()
    }

    /// The first record of an event's span.
    pub fn record(&mut self, span: Span) -> Option<Record> {
        let text = self.read(span.start, span.end);
        records(&text).into_iter().next()
    }

    /// The records between the last event read and this one, in order.
    /// Events the reader moved earlier (a tool load before its toolpath
    /// start) are not rescanned.
    pub fn gap(&mut self, span: Span) -> Vec<Record> {
        let out = if span.start > self.scanned { records(&self.read(self.scanned, span.start)) } else { Vec::new() };
        self.scanned = self.scanned.max(span.end);
        out
    }
}

/// Splits CL text into records: `$$` comments dropped, `$` continuations
/// joined; text records (PARTNO, PPRINT, INSERT, REMARK) are skipped.
pub fn records(text: &str) -> Vec<Record> {
    let mut out = Vec::new();
    let mut pending = String::new();
    for line in text.lines() {
        let line = match line.find("$$") {
            Some(i) => &line[..i],
            None => line,
        };
        let trimmed = line.trim_end();
        if let Some(body) = trimmed.strip_suffix('$') {
            pending.push_str(body);
            continue;
        }
        pending.push_str(trimmed);
        if let Some(r) = parse(&pending) {
            out.push(r);
        }
        pending.clear();
    }
    if let Some(r) = parse(&pending) {
        out.push(r);
    }
    out
}

fn parse(text: &str) -> Option<Record> {
    let text = text.trim();
    if text.is_empty() {
        return None;
    }
    let head = text.split(|c: char| c == '/' || c.is_whitespace()).next()?.to_ascii_uppercase();
    if matches!(head.as_str(), "PARTNO" | "PPRINT" | "INSERT" | "REMARK" | "PARTNO," | "") {
        return None;
    }
    let args = match text.split_once('/') {
        Some((_, rest)) => rest
            .split(',')
            .map(|a| a.trim().trim_matches(|c| c == '(' || c == ')').to_ascii_uppercase())
            .filter(|a| !a.is_empty())
            .collect(),
        None => Vec::new(),
    };
    Some(Record { word: head, args })
}

/// A FEDRAT record as written.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fedrat {
    pub value: f64,
    /// `Some(true)` per revolution (IPR, MMPR), `Some(false)` per minute
    /// (IPM, MMPM), `None` when no unit is named.
    pub per_rev: Option<bool>,
    /// Millimetres (MMPM, MMPR), inches (IPM, IPR), or not said.
    pub metric: Option<bool>,
}

impl Fedrat {
    pub fn from_record(r: &Record) -> Option<Fedrat> {
        if r.word != "FEDRAT" {
            return None;
        }
        let value = r.args.iter().find_map(|a| a.parse::<f64>().ok())?;
        let mut f = Fedrat { value, per_rev: None, metric: None };
        for a in &r.args {
            match a.as_str() {
                "IPM" => (f.per_rev, f.metric) = (Some(false), Some(false)),
                "MMPM" => (f.per_rev, f.metric) = (Some(false), Some(true)),
                "IPR" => (f.per_rev, f.metric) = (Some(true), Some(false)),
                "MMPR" => (f.per_rev, f.metric) = (Some(true), Some(true)),
                "PERMIN" | "UPM" => f.per_rev = Some(false),
                "PERREV" | "UPR" => f.per_rev = Some(true),
                _ => {}
            }
        }
        Some(f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn records_join_continuations_and_drop_comments() {
        let r = records("$$ FEDRAT/1\nCOOLNT/ FLOOD , $\n NOW $$ why\nPPRINT FEDRAT/2\nFEDRAT/ IPR, 0.01\n");
        assert_eq!(r[0], Record { word: "COOLNT".into(), args: vec!["FLOOD".into(), "NOW".into()] });
        assert_eq!(r.len(), 2);
        let f = Fedrat::from_record(&r[1]).unwrap();
        assert_eq!((f.value, f.per_rev, f.metric), (0.01, Some(true), Some(false)));
    }
}
