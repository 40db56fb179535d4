#[path = "flow_verification.rs"]
#[allow(dead_code)]
mod fv;
