mod font;
mod letter;
mod options;
