//! JSON objects read with their keys in file order (the summary's keys are in a stable,
//! meaningful order; `serde_json::Map` would sort them).
use std::fmt;

use serde::de::{Deserializer, MapAccess, Visitor};
use serde_json::Value;

/// A JSON object as (key, value) pairs in file order.
pub(crate) type Object = Vec<(String, Value)>;

struct ObjectVisitor;

impl<'de> Visitor<'de> for ObjectVisitor {
    type Value = Object;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a JSON object")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Object, A::Error> {
        let mut out = Vec::new();
        while let Some((k, v)) = map.next_entry::<String, Value>()? {
            out.push((k, v));
        }
        Ok(out)
    }
}

/// Parses a JSON object keeping its key order.
pub(crate) fn parse_object(text: &str) -> Result<Object, serde_json::Error> {
    let mut de = serde_json::Deserializer::from_str(text);
    let object = de.deserialize_map(ObjectVisitor)?;
    de.end()?;
    Ok(object)
}

/// The value of `key` in an object.
pub(crate) fn get<'a>(object: &'a Object, key: &str) -> Option<&'a Value> {
    object.iter().find(|(k, _)| k == key).map(|(_, v)| v)
}
