mod limits;
mod outline;
mod source;
mod units;
mod validate;
