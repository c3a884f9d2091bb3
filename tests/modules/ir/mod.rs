mod limits;
mod source;
mod units;
mod validate;
