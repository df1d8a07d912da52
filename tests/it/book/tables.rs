//! The reference tables, made from the code: the scene keys from `eulerdyn::scene::reference::keys()`, the CSV
//! columns from `eulerdyn::sample`'s column sets, the commands' flags from their clap definitions (`--help`). Each
//! sits in its book file between `<!-- generated: NAME … -->` and `<!-- end generated: NAME -->`.

use eulerdyn::motion::carrier;
use eulerdyn::sample::{BASE_COLUMNS, Column};
use eulerdyn::scene::Scene;
use eulerdyn::scene::reference::keys;

use super::blessing;
use crate::common::{eulerdyn, repo_path};

/// A table cell: `|` escaped, empty as `–`.
fn cell(text: &str) -> String {
    if text.is_empty() {
        "–".into()
    } else {
        text.replace('|', "\\|")
    }
}

/// The key tables, one section per table of the file.
pub(super) fn key_tables() -> String {
    let mut out = String::new();
    for table in keys() {
        let header = if table.header.is_empty() {
            "the top level"
        } else {
            table.header
        };
        out += &format!("\n### `{header}`\n\n{}.\n\n", table.about);
        out += "| key | type | unit | default | measured from | meaning |\n|---|---|---|---|---|---|\n";
        for k in table.keys {
            let cells = [k.kind, k.unit, k.default, k.origin, k.doc].map(cell);
            out += &format!("| `{}` | {} |\n", k.name, cells.join(" | "));
        }
    }
    out
}

/// The axes a column is expressed in, from its meaning.
fn axes(column: &Column) -> &'static str {
    if column.meaning.contains("space axes") {
        "space"
    } else if column.meaning.contains("body axes") {
        "body"
    } else {
        "–"
    }
}

/// The column table: every column in the order a run writes them, with the group that adds it (its name, as
/// `ColumnGroup::name`): the scene's own (`Scene::all_own_columns`), then a carrier's, a body's wheels', an
/// orbit's and the Earth's field (with a magnetic effect).
pub(super) fn column_table() -> String {
    let orbit =
        eulerdyn::orbit::CircularOrbit::new(eulerdyn::orbit::R_EARTH + 500e3, 0.0, 0.0, 0.0);
    let capabilities = [
        carrier::columns(),
        eulerdyn::wheels::columns(&["NAME".to_string()], true),
        eulerdyn::orbit::lvlh_columns(orbit),
        eulerdyn::orbit::field_columns(orbit, eulerdyn::orbit::DipoleField::new(3.12e-5, 0.0, 0.0)),
        shape_change_columns(),
    ];
    let groups: Vec<(String, Vec<Column>)> =
        std::iter::once(("always".to_string(), BASE_COLUMNS.to_vec()))
            .chain(
                (Scene::all_own_columns().groups.into_iter())
                    .chain(capabilities)
                    .map(|g| (format!("`{}`", g.name), g.columns)),
            )
            .collect();
    let names: Vec<&str> = groups
        .iter()
        .flat_map(|(_, g)| g.iter().map(|c| c.name.as_ref()))
        .collect();
    let mut unique = names.clone();
    unique.sort_unstable();
    unique.dedup();
    assert_eq!(unique.len(), names.len(), "a column written twice");
    let mut out =
        String::from("\n| column | unit | axes | written | meaning |\n|---|---|---|---|---|\n");
    for (group, columns) in &groups {
        for c in columns {
            out += &format!(
                "| `{}` | {} | {} | {group} | {} |\n",
                c.name,
                cell(c.unit),
                axes(c),
                cell(c.meaning)
            );
        }
    }
    out
}

/// The columns of a body that changes shape, with its centre of mass moving and one moving mass `NAME`.
fn shape_change_columns() -> eulerdyn::sample::ColumnGroup {
    use eulerdyn::shape_change::{Distribution, MassPath, MovingMass, Profile, ShapeChange};
    use nalgebra::{Matrix3, Vector3};
    let shape = ShapeChange::new(Distribution::Masses {
        rest_mass: 1.0,
        rest_c_b: Vector3::zeros(),
        rest_inertia_b: Matrix3::identity(),
        masses: vec![MovingMass {
            name: "NAME".into(),
            mass: 0.1,
            path: MassPath::Move {
                from: Vector3::zeros(),
                to: Vector3::x(),
                start: 0.0,
                duration: 1.0,
                profile: Profile::Smooth,
            },
        }],
    });
    std::sync::Arc::new(shape).columns()
}

/// The subcommands `eulerdyn --help` lists.
fn subcommands() -> Vec<String> {
    let help = eulerdyn(["--help"]).stdout;
    (help.lines())
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .map(String::from)
        .collect()
}

/// Each command's help, as a shell session the console test runs too.
pub(super) fn command_help() -> String {
    let mut out = String::new();
    for cmd in subcommands() {
        let help = eulerdyn([cmd.as_str(), "--help"]);
        assert_eq!(help.code, Some(0), "eulerdyn {cmd} --help: {}", help.stderr);
        let text: Vec<&str> = help.stdout.lines().map(str::trim_end).collect();
        out += &format!(
            "\n## `eulerdyn {cmd}`\n\n```console\n$ eulerdyn {cmd} --help\n{}\n```\n",
            text.join("\n")
        );
    }
    out
}

/// Replaces the generated section `name` of `file` with `made`; the stale file's name when they differ.
fn compare_or_bless(file: &str, name: &str, made: &str) -> Option<String> {
    let path = repo_path(file);
    let text = std::fs::read_to_string(&path).unwrap();
    let open = format!("<!-- generated: {name} ");
    let close = format!("<!-- end generated: {name} -->");
    let start = text
        .find(&open)
        .unwrap_or_else(|| panic!("{file}: no `{open}…-->`"));
    let start = start + text[start..].find("-->").unwrap() + "-->".len();
    let end = text
        .find(&close)
        .unwrap_or_else(|| panic!("{file}: no `{close}`"));
    if text[start..end] == *made {
        return None;
    }
    if blessing() {
        std::fs::write(&path, format!("{}{made}{}", &text[..start], &text[end..])).unwrap();
        return None;
    }
    Some(format!(
        "{file}: the `{name}` section differs from the code"
    ))
}

#[test]
fn the_reference_tables_are_made_from_the_code() {
    let stale: Vec<String> = [
        (
            "docs/book/src/reference/keys.md",
            "keys",
            key_tables() + "\n",
        ),
        (
            "docs/book/src/reference/columns.md",
            "columns",
            column_table() + "\n",
        ),
        (
            "docs/book/src/reference/commands.md",
            "commands",
            command_help() + "\n",
        ),
    ]
    .iter()
    .filter_map(|(file, name, made)| compare_or_bless(file, name, made))
    .collect();
    assert!(
        stale.is_empty(),
        "{}\n(EULERDYN_BLESS=1 cargo test --release --test it book rewrites them)",
        stale.join("\n")
    );
}

#[test]
fn the_key_tables_name_every_table_of_a_scene() {
    let made = key_tables();
    for table in [
        "[body]",
        "[[body.rotor]]",
        "[[effect]]",
        "[[event]]",
        "[solver]",
    ] {
        assert!(made.contains(&format!("`{table}`")), "{table}");
    }
    // The keys the hand-written table once left out.
    for key in ["`interpolation`", "`crosses`", "`extremum`", "`file`"] {
        assert!(made.contains(key), "{key}");
    }
}

/// Issue 57: the synopsis at the top of the commands page lacked `score`, `suite` and several flags. It is written by
/// hand (one line a command, the flags grouped); this checks it against the binary: every command, and every long
/// flag of each command's `--help` (but `--help`, `--quiet` and `--version`), appears in it.
#[test]
fn the_commands_synopsis_names_every_command_and_flag() {
    let page = std::fs::read_to_string(repo_path("docs/book/src/reference/commands.md")).unwrap();
    let synopsis: String = (page.lines())
        .skip_while(|l| !l.starts_with("```text"))
        .skip(1)
        .take_while(|l| !l.starts_with("```"))
        .collect::<Vec<_>>()
        .join("\n");
    let mut missing = Vec::new();
    for cmd in subcommands() {
        if !synopsis.contains(&format!("eulerdyn {cmd} ")) {
            missing.push(format!("eulerdyn {cmd}"));
            continue;
        }
        let help = eulerdyn([cmd.as_str(), "--help"]).stdout;
        // The options' lines: `  -o, --output <FILE>  …` or `      --method <M>  …`; a short form stands for both.
        for line in help
            .lines()
            .map(str::trim_start)
            .filter(|l| l.starts_with('-'))
        {
            let mut words = line.split_whitespace();
            let first = words.next().unwrap_or("").trim_end_matches(',');
            let (short, long) = match first.starts_with("--") {
                true => (None, first),
                false => (Some(first), words.next().unwrap_or("")),
            };
            let named = synopsis.contains(long)
                || short.is_some_and(|s| synopsis.contains(&format!("{s} ")));
            if !["--help", "--quiet", "--version"].contains(&long) && !named {
                missing.push(format!("eulerdyn {cmd} {long}"));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "not in the commands synopsis: {missing:?}"
    );
}
