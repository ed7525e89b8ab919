//! The field names of a struct that serde reads, asked of the struct itself, so that
//! a list of its keys is never written twice.

use serde::Deserialize;
use serde::de::value::Error;
use serde::de::{Error as _, Visitor};

/// A deserializer that reads nothing: serde's derived code hands a struct's field
/// names to `deserialize_struct`, which keeps them and stops.
struct FieldNames<'a>(&'a mut &'static [&'static str]);

impl<'de> serde::Deserializer<'de> for FieldNames<'_> {
    type Error = Error;

    fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Error> {
        Err(Error::custom("only a struct's field names are read"))
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _: &'static str,
        fields: &'static [&'static str],
        _: V,
    ) -> Result<V::Value, Error> {
        *self.0 = fields;
        Err(Error::custom("the field names are read"))
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes
        byte_buf option unit unit_struct newtype_struct seq tuple tuple_struct map
        enum identifier ignored_any
    }
}

/// The names of `T`'s fields as a file writes them (after serde's renames), in
/// their order in `T`; none for a type that serde does not read as a struct.
pub fn field_names<T: for<'de> Deserialize<'de>>() -> &'static [&'static str] {
    let mut fields: &'static [&'static str] = &[];
    let _ = T::deserialize(FieldNames(&mut fields));
    fields
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Deserialize)]
    struct Keys {
        first: u32,
        #[serde(rename = "second-key")]
        second: Option<String>,
    }

    /// The names are those a file writes, renames included: a file written with
    /// them reads back.
    #[test]
    fn a_structs_field_names_are_read_as_a_file_writes_them() {
        let names = field_names::<Keys>();
        assert_eq!(names, ["first", "second-key"]);
        let file = format!("{} = 3\n\"{}\" = \"x\"", names[0], names[1]);
        let keys: Keys = toml::from_str(&file).unwrap();
        assert_eq!((keys.first, keys.second.as_deref()), (3, Some("x")));
    }

    #[test]
    fn a_type_that_is_no_struct_has_none() {
        assert!(field_names::<u32>().is_empty());
    }
}
