//! Typed indexes into a post's tables.
//!
//! Every reference from one part of a [`crate::Post`] to another is an
//! index, and each table has its own index type, so that a variable's
//! index cannot be passed where a format's is expected (naga's
//! `Handle<T>` and oxc's index types are the models):
//!
//! | type | indexes | checked by |
//! |---|---|---|
//! | [`FormatId`] | [`crate::Post::formats`] | [`crate::validate`] |
//! | [`VarId`] | [`crate::Post::variables`] | [`crate::validate`] |
//! | [`FunctionId`] | [`crate::Post::functions`] | [`crate::validate`] |
//! | [`ScriptId`] | [`crate::Post::scripts`] | [`crate::validate`] |
//! | [`GlobalId`] | [`crate::Post::globals`] | [`crate::validate`] |
//! | [`LocalId`] | the slots of the running function's frame ([`crate::Function::slots`]) | [`crate::validate`] |
//!
//! Each is a `u16` on the wire: RON and JSON write the bare number
//! (`Var(3)`), so the text form of a post does not change with the types.

use serde::{Deserialize, Serialize};

macro_rules! index_types {
    ($( $(#[$doc:meta])* $name:ident; )*) => {$(
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
        #[serde(transparent)]
        pub struct $name(u16);

        impl $name {
            /// The index of a table entry.
            #[inline]
            pub const fn new(index: u16) -> Self {
                $name(index)
            }

            /// The index of entry `index`, or `None` when a table that
            /// long cannot be indexed (more than 65,536 entries).
            #[inline]
            pub fn from_usize(index: usize) -> Option<Self> {
                u16::try_from(index).ok().map($name)
            }

            /// The entry's position in its table.
            #[inline]
            pub const fn index(self) -> usize {
                self.0 as usize
            }

            /// The raw number, as written in RON.
            #[inline]
            pub const fn raw(self) -> u16 {
                self.0
            }
        }

        impl From<$name> for usize {
            #[inline]
            fn from(id: $name) -> usize {
                id.index()
            }
        }

        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                self.0.fmt(f)
            }
        }
    )*};
}

index_types! {
    /// Index of a [`crate::NumberFormat`] in [`crate::Post::formats`].
    FormatId;
    /// Index of a [`crate::Variable`] in [`crate::Post::variables`].
    VarId;
    /// Index of a [`crate::Function`] in [`crate::Post::functions`].
    FunctionId;
    /// Index of a [`crate::Script`] in [`crate::Post::scripts`].
    ScriptId;
    /// Index of a [`crate::Global`] in [`crate::Post::globals`].
    GlobalId;
    /// A slot of the running function's frame: a parameter or a local. A
    /// function's frame has
    /// [`crate::Function::slots`] slots, a handler body's starts empty; a
    /// frame grows to the highest slot stored, and a slot never stored
    /// reads as null, so no local index is out of range.
    LocalId;
}
