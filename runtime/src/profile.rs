//! Profiling hooks: the runtime says when a handler or a post function
//! starts and ends (`postc bench --profile`), and the caller measures. The
//! runtime reads no clock: timing is the observer's business. A run
//! without an observer pays one branch per call.

use postc_ir::FunctionId;

/// What starts running.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Frame {
    /// A handler, by its index in [`postc_ir::Post::handlers`].
    Handler(usize),
    /// A post function (native or script).
    Function(FunctionId),
}

/// Told of every handler run and function call, properly nested.
pub trait CallObserver {
    fn enter(&mut self, frame: Frame);
    /// The innermost frame entered ends.
    fn exit(&mut self);
}
