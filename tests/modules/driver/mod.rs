mod kinds;
mod library;
mod read_ahead;
mod ron_locate;
