mod outputs;
mod sink;
