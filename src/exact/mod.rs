//! Closed-form solutions: oracles for tests, `compare` and `accuracy`.
