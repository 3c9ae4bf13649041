//! The items of `src/replay/page.rs`.

use pegdyn::replay::page::*;

#[test]
fn no_embedded_text_can_end_its_script_element_early() {
    for (name, text) in [("three.js", THREE), ("licence", THREE_LICENSE)]
        .into_iter()
        .chain(SCRIPTS.iter().map(|s| ("page script", *s)))
    {
        let lower = text.to_ascii_lowercase();
        assert!(!lower.contains("</script"), "{name} holds </script");
        assert!(!lower.contains("<!--"), "{name} holds <!--");
    }
    assert!(
        !THREE_LICENSE.contains("*/"),
        "the licence would end its comment"
    );
}

#[test]
fn the_embedded_renderer_is_the_pinned_three_js() {
    assert!(THREE.contains(&format!("three.js {THREE_VERSION}")));
    assert!(THREE.contains("var PegdynThree="));
    assert!(THREE_LICENSE.starts_with("The MIT License"));
    let lock = include_str!(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/assets/replay/package-lock.json"
    ));
    assert!(
        lock.contains(&format!(
            "\"node_modules/three\": {{\n      \"version\": \"{THREE_VERSION}\""
        )),
        "package-lock.json pins another three.js"
    );
}

#[test]
fn every_placeholder_is_filled_and_the_title_escaped() {
    let page = document("a<b> & c", "{\"x\":1}");
    for name in ["TITLE", "STYLE", "DATA", "THREE", "APP"] {
        assert!(
            !page.contains(&format!("{{{{{name}}}}}")),
            "{name} left unfilled"
        );
    }
    assert!(page.contains("<title>a&lt;b&gt; &amp; c · pegdyn replay</title>"));
    assert!(
        page.contains("<script id=\"replay-data\" type=\"application/json\">{\"x\":1}</script>")
    );
}
