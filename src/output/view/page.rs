//! The HTML page: `assets/view/page.html` with its markers (`<!--@NAME-->`) replaced by the style, the run's data
//! (JSON) and the scripts — three.js from `assets/three/` and the page's own from `assets/view/` — all embedded in
//! the binary at build time.
//!
//! The three.js sources are ES modules that import each other; the page keeps them as inert text
//! (`<script type="text/plain">`) and its loader imports them from `blob:` URLs made in the page (no network).

use serde_json::{Value, json};

use super::ViewRun;

/// The page skeleton.
const PAGE: &str = include_str!("../../../assets/view/page.html");
/// The page's style.
const STYLE: &str = include_str!("../../../assets/view/view.css");
/// The controls, the readout and the legend (plain DOM).
const CONTROLS_JS: &str = include_str!("../../../assets/view/controls.js");
/// `window.eulerdyn`: the rows, interpolation between them, the clock (no three.js needed).
const STATE_JS: &str = include_str!("../../../assets/view/state.js");
/// The 3D scene, drawn with three.js.
const SCENE_JS: &str = include_str!("../../../assets/view/scene.js");
/// Imports three.js from blob: URLs and starts the scene.
const LOADER_JS: &str = include_str!("../../../assets/view/loader.js");

/// three.js (`build/three.core.js`, `build/three.module.js`, `examples/jsm/controls/OrbitControls.js`); see
/// `assets/three/README.md` for the version.
pub const THREE_CORE: &str = include_str!("../../../assets/three/three.core.js");
/// three.js's module (`build/three.module.js`).
pub const THREE_MODULE: &str = include_str!("../../../assets/three/three.module.js");
/// OrbitControls (`examples/jsm/controls/OrbitControls.js`).
pub const THREE_ORBIT: &str = include_str!("../../../assets/three/OrbitControls.js");

/// Whether `text` can sit in an HTML `<script>` element as it is: it must not close the element (`</script`)
/// nor open an HTML comment (`<!--`), which would change how the parser finds the element's end.
pub fn safe_in_script(text: &str) -> bool {
    let lower = text.to_ascii_lowercase();
    !lower.contains("</script") && !lower.contains("<!--")
}

/// The page of `run`.
pub fn render(run: &ViewRun) -> String {
    let data = data_json(run);
    let title = format!(
        "eulerdyn view — {}",
        run.geometry.json["name"]
            .as_str()
            .map(str::to_string)
            .unwrap_or_else(|| run.file.display().to_string())
    );
    let mut html = String::with_capacity(PAGE.len() + data.len() + THREE_CORE.len() * 3 / 2);
    let mut rest = PAGE;
    while let Some(start) = rest.find("<!--@") {
        html.push_str(&rest[..start]);
        let after = &rest[start + 5..];
        let end = after.find("-->").unwrap_or(after.len());
        let name = &after[..end];
        match name {
            "TITLE" => html.push_str(&escape_html(&title)),
            "STYLE" => html.push_str(STYLE),
            "DATA" => html.push_str(&data),
            "THREE_CORE" => html.push_str(THREE_CORE),
            "THREE_MODULE" => html.push_str(THREE_MODULE),
            "THREE_ORBIT" => html.push_str(THREE_ORBIT),
            "CONTROLS_JS" => html.push_str(CONTROLS_JS),
            "STATE_JS" => html.push_str(STATE_JS),
            "SCENE_JS" => html.push_str(SCENE_JS),
            "LOADER_JS" => html.push_str(LOADER_JS),
            _ => {}
        }
        rest = after.get(end + 3..).unwrap_or("");
    }
    html.push_str(rest);
    html
}

/// The run as the page's JSON: the kept rows (numbers that read back to the same f64), the decimation, the
/// geometry, the notes and the located events (`event`, `t`, `value`, `direction`, `when`: all of them, not
/// decimated). `<` is written `\u003c`, so that no string can end the `<script>` element.
pub fn data_json(run: &ViewRun) -> String {
    let rows = &run.rows;
    let table: Vec<&[f64]> = (0..rows.len()).map(|k| rows.row(k)).collect();
    let mut notes = run.geometry.notes.clone();
    if rows.stride > 1 {
        notes.push(run.rows_note());
    }
    let doc: Value = json!({
        "eulerdyn_version": env!("CARGO_PKG_VERSION"),
        "file": run.file.file_name().map(|n| n.to_string_lossy().into_owned()),
        "columns": rows.columns,
        "rows": table,
        "rows_in_run": rows.rows_in_run,
        "stride": rows.stride,
        "max_drawn_rows": super::MAX_DRAWN_ROWS,
        "rows_note": run.rows_note(),
        "notes": notes,
        "geometry": run.geometry.json,
        "events": events_json(run),
    });
    doc.to_string().replace('<', "\\u003c")
}

/// The located events as JSON objects, in time order.
fn events_json(run: &ViewRun) -> Value {
    (run.events.iter())
        .map(|e| {
            json!({
                "event": e.event,
                "t": e.t,
                "value": e.value,
                "direction": e.direction,
                "when": e.when,
            })
        })
        .collect()
}

/// `text` with `&`, `<`, `>` and `"` escaped for HTML.
fn escape_html(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_embedded_scripts_cannot_end_their_script_elements() {
        for (name, text) in [
            ("three.core.js", THREE_CORE),
            ("three.module.js", THREE_MODULE),
            ("OrbitControls.js", THREE_ORBIT),
            ("controls.js", CONTROLS_JS),
            ("state.js", STATE_JS),
            ("scene.js", SCENE_JS),
            ("loader.js", LOADER_JS),
            ("view.css", STYLE),
        ] {
            assert!(safe_in_script(text), "{name} contains </script or <!--");
        }
        assert!(!safe_in_script("a</SCRIPT>b"));
    }

    #[test]
    fn the_loader_finds_the_module_specifiers_it_rewrites() {
        // loader.js replaces these to import the modules from blob: URLs.
        assert!(THREE_MODULE.contains("from './three.core.js';"));
        assert!(THREE_ORBIT.contains("from 'three';"));
        assert!(LOADER_JS.contains("'./three.core.js'") && LOADER_JS.contains("'three'"));
    }
}
