//! Exact numbers: parsing and printing.
