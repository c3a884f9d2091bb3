//! The eight controllers `MACHIN/name` chooses, each a VcPost post and an
//! options file embedded in the binary (`corpus/posts/postp/NAME.VcPost`
//! and `NAME.ron`), and the machine's rotary axes from MACHIN's axis type.

use std::fmt;

/// Mill or lathe: which words a controller accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Mill,
    Lathe,
}

/// A controller of the seed's list.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Controller {
    AcornM,
    AcornL,
    FanucM,
    FanucL,
    HaasM,
    HaasL,
    TormM,
    TormL,
}

impl Controller {
    pub const ALL: [Controller; 8] = [
        Controller::AcornM,
        Controller::AcornL,
        Controller::FanucM,
        Controller::FanucL,
        Controller::HaasM,
        Controller::HaasL,
        Controller::TormM,
        Controller::TormL,
    ];

    /// The MACHIN name (`FANUCM`).
    pub fn name(self) -> &'static str {
        match self {
            Controller::AcornM => "ACORNM",
            Controller::AcornL => "ACORNL",
            Controller::FanucM => "FANUCM",
            Controller::FanucL => "FANUCL",
            Controller::HaasM => "HAASM",
            Controller::HaasL => "HAASL",
            Controller::TormM => "TORMM",
            Controller::TormL => "TORML",
        }
    }

    /// The controller a MACHIN name means (any case).
    pub fn from_name(name: &str) -> Option<Controller> {
        Controller::ALL.into_iter().find(|c| c.name().eq_ignore_ascii_case(name.trim()))
    }

    pub fn kind(self) -> Kind {
        match self {
            Controller::AcornM | Controller::FanucM | Controller::HaasM | Controller::TormM => Kind::Mill,
            _ => Kind::Lathe,
        }
    }

    /// The embedded post's file name, as diagnostics show it.
    pub fn post_name(self) -> String {
        format!("<embedded>/postp/{}.VcPost", self.name())
    }

    /// The embedded post.
    pub fn post_source(self) -> &'static [u8] {
        match self {
            Controller::AcornM => include_bytes!("../../corpus/posts/postp/ACORNM.VcPost"),
            Controller::AcornL => include_bytes!("../../corpus/posts/postp/ACORNL.VcPost"),
            Controller::FanucM => include_bytes!("../../corpus/posts/postp/FANUCM.VcPost"),
            Controller::FanucL => include_bytes!("../../corpus/posts/postp/FANUCL.VcPost"),
            Controller::HaasM => include_bytes!("../../corpus/posts/postp/HAASM.VcPost"),
            Controller::HaasL => include_bytes!("../../corpus/posts/postp/HAASL.VcPost"),
            Controller::TormM => include_bytes!("../../corpus/posts/postp/TORMM.VcPost"),
            Controller::TormL => include_bytes!("../../corpus/posts/postp/TORML.VcPost"),
        }
    }

    /// The embedded default options file (RON).
    pub fn default_options(self) -> &'static str {
        match self {
            Controller::AcornM => include_str!("../../corpus/posts/postp/ACORNM.ron"),
            Controller::AcornL => include_str!("../../corpus/posts/postp/ACORNL.ron"),
            Controller::FanucM => include_str!("../../corpus/posts/postp/FANUCM.ron"),
            Controller::FanucL => include_str!("../../corpus/posts/postp/FANUCL.ron"),
            Controller::HaasM => include_str!("../../corpus/posts/postp/HAASM.ron"),
            Controller::HaasL => include_str!("../../corpus/posts/postp/HAASL.ron"),
            Controller::TormM => include_str!("../../corpus/posts/postp/TORMM.ron"),
            Controller::TormL => include_str!("../../corpus/posts/postp/TORML.ron"),
        }
    }
}

impl fmt::Display for Controller {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The rotary axes of MACHIN's axis type (mills only): 0 none, 1 A, 2 B,
/// 3 and 4 A and B, 5 A and C, 6 B and C.
pub fn rotary_axes(axis_type: u8) -> &'static [char] {
    match axis_type {
        1 => &['A'],
        2 => &['B'],
        3 | 4 => &['A', 'B'],
        5 => &['A', 'C'],
        6 => &['B', 'C'],
        _ => &[],
    }
}

/// The MACHIN names, for messages.
pub fn names() -> String {
    Controller::ALL.iter().map(|c| c.name()).collect::<Vec<_>>().join(", ")
}
