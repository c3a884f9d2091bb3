mod cimco;
