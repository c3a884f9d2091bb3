//! Vectric products and what their post processors do not support, from
//! the Vectric post processor guide (the 2012 Vectric post guide, "Post Processor differences
//! between different Vectric Products", products as of January 2012):
//!
//! | product | not supported |
//! |---|---|
//! | Cut3D 1.025 | `DIRECT_OUTPUT`, `SUBSTITUTE`, `TAPE_SPLITTING`, `RAPID_PLUNGE_TO_STARTZ`, `ROTARY_WRAP_X`/`_Y`, `FIRST_PLUNGE_MOVE`, and the variables below |
//! | PhotoVCarve 1.102 | every arc section and arc variable, `DIRECT_OUTPUT`, `PRINT_DIRECT`, `SPINDLE_SPEED_RANGE`, `SUBSTITUTE`, `TAPE_SPLITTING`, `RAPID_PLUNGE_TO_STARTZ`, `ROTARY_WRAP_X`/`_Y`, `FIRST_PLUNGE_MOVE`, `NEW_SEGMENT`, and the variables below |
//! | Cut2D 1.100 | `ROTARY_WRAP_X`/`_Y`, `[WRAP_DIA]`; accepted but not used: `RAPID_PLUNGE_TO_STARTZ`, `[TOOLPATH_NOTES]`, `[FILE_NOTES]` |
//! | VCarve, Aspire | everything |
//!
//! The variables Cut3D and PhotoVCarve do not support: `[WRAP_DIA]`
//! `[X_ORIGIN_POS]` `[Y_ORIGIN_POS]` `[Z_ORIGIN]` `[XY_ORIGIN]`
//! `[TOOLS_USED]` `[TOOLPATH_NOTES]` `[FILE_NOTES]` `[TIME]` `[DATE]`
//! `[TOOLPATHS_OUTPUT]`.

use postc_ir::{Post, Quantity, Section};

/// A Vectric product (`postc check --product`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Product {
    Cut2d,
    Vcarve,
    Aspire,
    Cut3d,
    PhotoVcarve,
}

impl Product {
    /// Every product, with the name `--product` takes.
    pub const ALL: &'static [(Product, &'static str)] = &[
        (Product::Cut2d, "cut2d"),
        (Product::Vcarve, "vcarve"),
        (Product::Aspire, "aspire"),
        (Product::Cut3d, "cut3d"),
        (Product::PhotoVcarve, "photovcarve"),
    ];

    /// The product's name as Vectric writes it.
    pub fn title(self) -> &'static str {
        match self {
            Product::Cut2d => "Cut2D",
            Product::Vcarve => "VCarve",
            Product::Aspire => "Aspire",
            Product::Cut3d => "Cut3D",
            Product::PhotoVcarve => "PhotoVCarve",
        }
    }

    /// The product `--product NAME` names.
    pub fn from_name(name: &str) -> Option<Product> {
        Product::ALL.iter().find(|(_, n)| n.eq_ignore_ascii_case(name)).map(|(p, _)| *p)
    }
}

/// How far a product goes with a construct.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Support {
    /// Not supported.
    No,
    /// Accepted, but the product does not use it.
    Ignored,
}

const ORIGIN_AND_NOTES: &[Quantity] = &[
    Quantity::WrapDiameter,
    Quantity::XOrigin,
    Quantity::YOrigin,
    Quantity::ZOriginText,
    Quantity::XyOriginText,
    Quantity::ToolsUsed,
    Quantity::ToolpathNotes,
    Quantity::FileNotes,
    Quantity::Time,
    Quantity::Date,
    Quantity::ToolpathsOutput,
];

/// Arc quantities (PhotoVCarve has no arc support).
pub const ARC_QUANTITIES: &[Quantity] = &[
    Quantity::I,
    Quantity::J,
    Quantity::K,
    Quantity::IA,
    Quantity::JA,
    Quantity::KA,
    Quantity::ArcStartX,
    Quantity::ArcStartY,
    Quantity::ArcMidX,
    Quantity::ArcMidY,
    Quantity::ArcMidXI,
    Quantity::ArcMidYI,
    Quantity::Radius,
    Quantity::Angle,
];

/// Whether a section is an arc section.
pub fn is_arc_section(s: Section) -> bool {
    s.name().contains("ARC")
}

/// The global statements a post uses that the product does not support,
/// each named as the post writes it.
pub fn statements(post: &Post, product: Product) -> Vec<(&'static str, Support)> {
    use Support::*;
    let o = &post.options;
    let i = &post.info;
    let wrap = o.rotary_wrap.map(|w| match w.axis {
        postc_ir::post::WrappedAxis::X => "ROTARY_WRAP_X",
        postc_ir::post::WrappedAxis::Y => "ROTARY_WRAP_Y",
    });
    let used: Vec<(&'static str, bool)> = vec![
        ("DIRECT_OUTPUT", i.direct_output.is_some()),
        ("PRINT_DIRECT", i.print_direct),
        ("SPINDLE_SPEED_RANGE", o.spindle_speed_range.is_some()),
        ("SUBSTITUTE", !o.substitutions.is_empty()),
        ("TAPE_SPLITTING", o.tape_splitting.is_some()),
        ("RAPID_PLUNGE_TO_STARTZ", i.rapid_plunge_to_start_z),
        (wrap.unwrap_or("ROTARY_WRAP_X"), wrap.is_some()),
    ];
    let unsupported: &[(&str, Support)] = match product {
        Product::Vcarve | Product::Aspire => &[],
        Product::Cut2d => &[("ROTARY_WRAP_X", No), ("ROTARY_WRAP_Y", No), ("RAPID_PLUNGE_TO_STARTZ", Ignored)],
        Product::Cut3d => &[
            ("DIRECT_OUTPUT", No),
            ("SUBSTITUTE", No),
            ("TAPE_SPLITTING", No),
            ("RAPID_PLUNGE_TO_STARTZ", No),
            ("ROTARY_WRAP_X", No),
            ("ROTARY_WRAP_Y", No),
        ],
        Product::PhotoVcarve => &[
            ("DIRECT_OUTPUT", No),
            ("PRINT_DIRECT", No),
            ("SPINDLE_SPEED_RANGE", No),
            ("SUBSTITUTE", No),
            ("TAPE_SPLITTING", No),
            ("RAPID_PLUNGE_TO_STARTZ", No),
            ("ROTARY_WRAP_X", No),
            ("ROTARY_WRAP_Y", No),
        ],
    };
    used.into_iter()
        .filter(|(_, on)| *on)
        .filter_map(|(name, _)| unsupported.iter().find(|(n, _)| *n == name).map(|(n, s)| (*n, *s)))
        .collect()
}

/// Whether the product supports a section.
pub fn section(product: Product, s: Section) -> Option<Support> {
    let no = match product {
        Product::Vcarve | Product::Aspire | Product::Cut2d => false,
        Product::Cut3d => s == Section::FirstPlungeMove,
        Product::PhotoVcarve => matches!(s, Section::FirstPlungeMove | Section::NewSegment) || is_arc_section(s),
    };
    no.then_some(Support::No)
}

/// Whether the product supports printing a quantity.
pub fn quantity(product: Product, q: Quantity) -> Option<Support> {
    match product {
        Product::Vcarve | Product::Aspire => None,
        Product::Cut2d => match q {
            Quantity::WrapDiameter => Some(Support::No),
            Quantity::ToolpathNotes | Quantity::FileNotes => Some(Support::Ignored),
            _ => None,
        },
        Product::Cut3d => ORIGIN_AND_NOTES.contains(&q).then_some(Support::No),
        Product::PhotoVcarve => (ORIGIN_AND_NOTES.contains(&q) || ARC_QUANTITIES.contains(&q)).then_some(Support::No),
    }
}
