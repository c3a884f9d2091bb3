mod check;
mod grammar;
