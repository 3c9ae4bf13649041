//! The replay page: the HTML template with its style, the renderer (three.js,
//! bundled once by `assets/replay/build.sh` and embedded here), the page's
//! own scripts and the run's JSON, all in one document. Everything is
//! included at compile time, so the binary needs no file at run time and
//! the page no network.
//!
//! The page's scripts (in `src/replay/page/`, plain scripts sharing the
//! global `Replay`): `geometry.js` (profiles, the radial exaggeration),
//! `bodies.js` (peg and block meshes), `markers.js` (contacts, force
//! arrows, the wrist, the path), `view.js` (renderer, camera, orbit
//! controls), `plots.js` (the linked plots), `main.js` (timeline, controls,
//! the state readable as `window.pegdynReplay`).

/// The template; `{{TITLE}}`, `{{STYLE}}`, `{{DATA}}`, `{{THREE}}` and
/// `{{APP}}` are filled in.
const TEMPLATE: &str = include_str!("page/replay.html");
/// The page's style sheet.
const STYLE: &str = include_str!("page/replay.css");
/// The page's scripts, in load order.
#[doc(hidden)]
pub const SCRIPTS: [&str; 6] = [
    include_str!("page/geometry.js"),
    include_str!("page/bodies.js"),
    include_str!("page/markers.js"),
    include_str!("page/view.js"),
    include_str!("page/plots.js"),
    include_str!("page/main.js"),
];
/// three.js's parts that the page uses, as one classic script defining the
/// global `PegdynThree` (see `assets/replay/entry.js` for why a bundle).
pub const THREE: &str = include_str!("../../assets/replay/three.bundle.min.js");
/// three.js's licence (MIT), repeated in every page that embeds it.
pub const THREE_LICENSE: &str = include_str!("../../assets/replay/LICENSE-three.txt");
/// The pinned three.js version of [`THREE`].
pub const THREE_VERSION: &str = "0.187.0";

/// `text` made safe as HTML text (the title).
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// The page for the run's JSON `data` (as written by
/// [`super::json::replay`]), titled `title`.
pub fn document(title: &str, data: &str) -> String {
    let three = format!(
        "/*! three.js {THREE_VERSION}, embedded under its licence:\n{THREE_LICENSE}*/\n{THREE}"
    );
    let app = SCRIPTS.join("\n");
    let mut out = String::with_capacity(TEMPLATE.len() + three.len() + app.len() + data.len());
    let mut rest = TEMPLATE;
    while let Some(start) = rest.find("{{") {
        let Some(len) = rest[start..].find("}}") else {
            break;
        };
        out.push_str(&rest[..start]);
        match &rest[start + 2..start + len] {
            "TITLE" => out.push_str(&escape(title)),
            "STYLE" => out.push_str(STYLE),
            "DATA" => out.push_str(data),
            "THREE" => out.push_str(&three),
            "APP" => out.push_str(&app),
            other => {
                out.push_str("{{");
                out.push_str(other);
                out.push_str("}}");
            }
        }
        rest = &rest[start + len + 2..];
    }
    out.push_str(rest);
    out
}
