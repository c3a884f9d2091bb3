mod read_ahead;
mod ron_locate;
