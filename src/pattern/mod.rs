//! The pattern language (issue 3): to be written.
