mod native;
mod synthetic;
