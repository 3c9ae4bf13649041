//! The items of `src/scene/document.rs`.

use pegdyn::error::{Location, SceneError, SceneErrors};
use pegdyn::scene::document::*;
use serde::Deserialize;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[allow(dead_code)]
struct Body {
    peg: Peg,
}
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[allow(dead_code)]
struct Peg {
    mass: f64,
    n: usize,
}

fn err(text: &str) -> SceneErrors {
    Document::parse(text)
        .and_then(|d| d.body::<Body>())
        .unwrap_err()
}

#[test]
fn structural_errors_name_the_dotted_field() {
    let e = err("kind = 'x'\n[peg]\nn = 1\n");
    assert!(matches!(&e.errors[0].error, SceneError::Missing { field } if field == "peg.mass"));
    let e = err("kind = 'x'\n[peg]\nmass = 1.0\nn = 1\nmas = 2\n");
    assert!(matches!(&e.errors[0].error, SceneError::Unknown { field, .. } if field == "peg.mas"));
    assert_eq!(e.errors[0].at, Some(Location { line: 5, column: 1 }));
    let e = err("kind = 'x'\n[peg]\nmass = true\nn = 1\n");
    assert!(
        matches!(&e.errors[0].error, SceneError::WrongType { field, found, .. } if field == "peg.mass" && found.contains("true")),
        "{e}"
    );
    let e = err("kind = 'x'\n[peg]\nmass = 1.0\nn = -3\n");
    assert!(
        e.to_string().contains("peg.n") && e.to_string().contains("-3"),
        "{e}"
    );
}

#[test]
fn kind_is_required_and_a_string() {
    let e = Document::parse("[peg]\n").err().unwrap();
    assert!(matches!(&e.errors[0].error, SceneError::Missing { field } if field == "kind"));
    let e = Document::parse("kind = 3\n").err().unwrap();
    assert!(matches!(&e.errors[0].error, SceneError::WrongType { field, .. } if field == "kind"));
}

#[test]
fn wrong_types_are_named_in_toml_words_with_the_value_written() {
    for (value, found) in [
        ("{ a = 1 }", "a table `{ a = 1 }`"),
        ("1979-05-27", "a datetime `1979-05-27`"),
        ("[1, 2]", "an array `[1, 2]`"),
        ("1.5", "a float `1.5`"),
        ("\"x\"", "a string `\"x\"`"),
        ("99999999999999999999", ""),
    ] {
        let e = Document::parse(&format!("kind = 'x'\n[peg]\nmass = 1.0\nn = {value}\n"))
            .and_then(|d| d.body::<Body>())
            .unwrap_err()
            .to_string();
        assert!(e.contains("`peg.n`") && e.contains(found), "{value}: {e}");
        for jargon in ["u64", "usize", "i128", "map", "sequence", "floating point"] {
            assert!(!e.contains(jargon), "{value}: {jargon} in {e}");
        }
    }
    let e = err("kind = 'x'\n[peg]\nmass = 1.0\nn = -3\n").to_string();
    assert!(
        e.contains("`peg.n` = -3: must be a non-negative integer"),
        "{e}"
    );
}

#[test]
fn an_array_element_is_located_on_its_own_line() {
    let doc = Document::parse("kind = 'x'\n[grid]\nv = [\n  1.0,\n  2.0,\n]\n").unwrap();
    let e = doc.locate_all(SceneErrors::from(SceneError::invalid(
        "grid.v[1]",
        2.0,
        "test",
    )));
    assert_eq!(e.errors[0].at, Some(Location { line: 5, column: 3 }));
    assert_eq!(doc.found_at("grid.v[1]").as_deref(), Some("a float `2.0`"));
    // An index beyond the array falls back to the array itself.
    let e = doc.locate_all(SceneErrors::from(SceneError::invalid("grid.v[7]", 0, "x")));
    assert_eq!(e.errors[0].at, Some(Location { line: 3, column: 5 }));
}

#[test]
fn integers_past_64_bits_are_refused_where_they_stand() {
    let text = "kind = \"pendulum\"\n[limits]\nmax_steps = 10000000000000000000\n\
                [grid]\nn = [1, 0x8000000000000000, -9223372036854775808]\n\
                deep = { a = { b = -9223372036854775809 } }\n";
    let e = Document::parse(text).err().unwrap();
    let got: Vec<(String, String, usize)> = e
        .errors
        .iter()
        .map(|l| match &l.error {
            SceneError::Invalid { field, value, .. } => {
                (field.clone(), value.clone(), l.at.unwrap().line)
            }
            other => panic!("{other}"),
        })
        .collect();
    assert_eq!(
        got,
        [
            ("limits.max_steps".into(), "10000000000000000000".into(), 3),
            ("grid.n[1]".into(), "0x8000000000000000".into(), 5),
            ("grid.deep.a.b".into(), "-9223372036854775809".into(), 6),
        ]
    );
    assert!(e.to_string().contains("9223372036854775807"), "{e}");
    // The edges of the range are TOML integers.
    let edge = "kind = \"k\"\na = 9223372036854775807\nb = -9223372036854775808\n";
    assert!(Document::parse(edge).is_ok());
}

#[test]
fn locations_are_one_based() {
    assert_eq!(location("ab\ncd", 4), Location { line: 2, column: 2 });
    assert_eq!(location("", 0), Location { line: 1, column: 1 });
}
