//! Integration methods and the streaming driver.
