//! A corpus of bad scenes and bad command lines, each run through the real binary with `check` and `run -o`.
//!
//! Every case must exit 2 (never panic), name the scene file, name the key at fault (and the flag, for values
//! from the command line), give the right line where the parser knows it, and create no output file.
//!
//! A case's expected line is marked in its text with a `# <--` comment on that line.

use std::path::{Path, PathBuf};

use crate::common::{FREE_SCENE, dir_entries, eulerdyn, read_csv, write_file};

/// A prescribed-motion scene: the tilted thin disk.
const DISK_SCENE: &str = r#"name = "disk"

[body]
mass = 2.0
shape = { type = "thin_disk", radius = 0.3 }

[motion]
type = "fixed_axis"
tilt_deg = 30
rate = 10.0

[solver]
t_end = 1.0

[output]
every = 0.1
"#;

/// What the scene path points at.
enum Input {
    Text(String),
    Bytes(Vec<u8>),
    Directory,
    Missing,
}

/// One bad input and what its message must contain.
struct Case {
    name: &'static str,
    input: Input,
    /// Extra `run` arguments; cases with flags are not run through `check` (it takes none).
    flags: Vec<&'static str>,
    /// Substrings the message must contain (the key in backticks, a flag, a word of the problem).
    expect: Vec<String>,
    /// The line the message must give (`file:line:`).
    line: Option<usize>,
    /// Whether the message must name the scene file (clap's own errors about a flag's syntax do not).
    names_file: bool,
}

/// `text` with `from` replaced by `to` (which must occur).
fn edit(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "{from:?} not in the base scene");
    text.replacen(from, to, 1)
}

/// The free scene edited.
fn free(from: &str, to: &str) -> String {
    edit(FREE_SCENE, from, to)
}

/// The disk scene edited.
fn disk(from: &str, to: &str) -> String {
    edit(DISK_SCENE, from, to)
}

/// The free scene followed by `more`.
fn free_plus(more: &str) -> String {
    format!("{FREE_SCENE}{more}")
}

/// The 1-based line of the `# <--` marker, if any.
fn marked_line(text: &str) -> Option<usize> {
    text.lines()
        .position(|l| l.contains("# <--"))
        .map(|i| i + 1)
}

/// A case whose message must contain the key `key` (in backticks) and the words of `expect`.
fn case(name: &'static str, text: String, key: &str, expect: &[&str]) -> Case {
    let mut all = vec![format!("`{key}`")];
    all.extend(expect.iter().map(|s| s.to_string()));
    Case {
        name,
        line: marked_line(&text),
        input: Input::Text(text),
        flags: Vec::new(),
        expect: all,
        names_file: true,
    }
}

/// A case without a key: the file as a whole is at fault.
fn whole_file(name: &'static str, input: Input, expect: &[&str], line: Option<usize>) -> Case {
    Case {
        name,
        input,
        flags: Vec::new(),
        expect: expect.iter().map(|s| s.to_string()).collect(),
        line,
        names_file: true,
    }
}

/// A bad command-line value on a valid scene: the message names the key and the flag.
fn flag(name: &'static str, flags: &[&'static str], key: &str) -> Case {
    Case {
        name,
        input: Input::Text(FREE_SCENE.to_string()),
        flags: flags.to_vec(),
        expect: vec![key.to_string(), flags[0].to_string()],
        line: None,
        names_file: true,
    }
}

fn cases() -> Vec<Case> {
    let mut cases = vec![
        // The file itself.
        whole_file("empty file", Input::Text(String::new()), &["empty"], None),
        case(
            "a file of comments only",
            "\n  \n# only a comment\n".into(),
            "body",
            &["missing"],
        ),
        whole_file(
            "non-UTF-8 bytes",
            Input::Bytes(b"[body]\nmass = 1.0 # \xff\xfe\n".to_vec()),
            &["UTF-8"],
            Some(2),
        ),
        whole_file("a directory", Input::Directory, &["directory"], None),
        whole_file("a missing file", Input::Missing, &["cannot read"], None),
        whole_file(
            "TOML syntax error",
            Input::Text(free("mass = 1.0", "mass = = 1.0 # <--")),
            &[],
            Some(4),
        ),
        whole_file(
            "unterminated string",
            Input::Text(free("name = \"free\"", "name = \"free # <--")),
            &[],
            Some(1),
        ),
        whole_file(
            "duplicate key",
            Input::Text(free("mass = 1.0", "mass = 1.0\nmass = 2.0 # <--")),
            &["mass"],
            Some(5),
        ),
        // Unknown keys.
        case(
            "unknown key at top level",
            free("name = \"free\"", "name = \"free\"\ncolour = \"red\" # <--"),
            "colour",
            &["unknown"],
        ),
        case(
            "unknown key in [body]",
            free("mass = 1.0", "mass = 1.0\ndensity = 3.0 # <--"),
            "body.density",
            &["unknown"],
        ),
        case(
            "unknown key in [solver]",
            free("t_end = 1.0", "t_end = 1.0\ntolerance = 1e-6 # <--"),
            "solver.tolerance",
            &["unknown"],
        ),
        case(
            "unknown key in [output]",
            free("every = 0.1", "every = 0.1\nformat = \"csv\" # <--"),
            "output.format",
            &["unknown"],
        ),
        case(
            "unknown key in an effect (the second)",
            free_plus(
                "\n[[effect]]\ntype = \"damping\"\nc = 0.1\n\n[[effect]]\ntype = \"damping\"\nc = 0.1\nk = 2.0 # <--\n",
            ),
            "effect[1].k",
            &["unknown"],
        ),
        case(
            "unknown key in an inline effect array",
            free(
                "name = \"free\"",
                "name = \"free\"\neffect = [{ type = \"damping\", c = 0.1 }, { type = \"damping\", c = 0.1, k = 2 }] # <--",
            ),
            "effect[1].k",
            &["unknown"],
        ),
        case(
            "unknown key in a shape",
            free(
                "inertia = [1.0, 2.0, 3.0]",
                "shape = { type = \"sphere\", radius = 1.0, colour = 2 } # <--",
            ),
            "body.shape.colour",
            &["unknown"],
        ),
        case(
            "unknown key in [motion]",
            disk("rate = 10.0", "rate = 10.0\nspin = 3.0 # <--"),
            "motion.spin",
            &["unknown"],
        ),
        case(
            "unknown key in [initial]",
            free(
                "omega = [0.3, 0.0, 2.0]",
                "omega = [0.3, 0.0, 2.0]\nalpha = 1 # <--",
            ),
            "initial.alpha",
            &["unknown"],
        ),
        case(
            "key of another shape type",
            free(
                "inertia = [1.0, 2.0, 3.0]",
                "shape = { type = \"sphere\", radius = 1.0, height = 2.0 } # <--",
            ),
            "body.shape.height",
            &["sphere"],
        ),
        case(
            "key of another effect type",
            free_plus("\n[[effect]]\ntype = \"torque\"\nvalue = [0.0, 0.0, 1.0]\nc = 0.1 # <--\n"),
            "effect[0].c",
            &["torque"],
        ),
        // Missing keys.
        case(
            "missing [body]",
            free("[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n", ""),
            "body",
            &["missing"],
        ),
        case(
            "missing body.mass",
            free("[body]\nmass = 1.0\n", "[body] # <--\n"),
            "body.mass",
            &["missing"],
        ),
        case(
            "missing solver.t_end",
            free(
                "[solver]\nt_end = 1.0",
                "[solver] # <--\nmethod = \"dop853\"",
            ),
            "solver.t_end",
            &["missing"],
        ),
        case(
            "missing [solver]",
            free("[solver]\nt_end = 1.0\n", ""),
            "solver",
            &["missing"],
        ),
        case(
            "missing output.every",
            free("[output]\nevery = 0.1", "[output] # <--"),
            "output.every",
            &["missing"],
        ),
        case(
            "missing shape type",
            free(
                "inertia = [1.0, 2.0, 3.0]",
                "shape = { radius = 1.0 } # <--",
            ),
            "body.shape.type",
            &["missing"],
        ),
        case(
            "missing shape dimension",
            free(
                "inertia = [1.0, 2.0, 3.0]",
                "shape = { type = \"cylinder\", radius = 1.0 } # <--",
            ),
            "body.shape.height",
            &["missing"],
        ),
        case(
            "missing effect type",
            free_plus("\n[[effect]] # <--\nc = 0.1\n"),
            "effect[0].type",
            &["missing"],
        ),
        case(
            "missing gravity pivot",
            free_plus(
                "\n[[effect]]\ntype = \"damping\"\nc = 0.1\n\n[[effect]] # <--\ntype = \"gravity\"\n",
            ),
            "effect[1].pivot",
            &["missing"],
        ),
        case(
            "missing motion type",
            disk("type = \"fixed_axis\"\n", ""),
            "motion.type",
            &["missing"],
        ),
        // Wrong types and values that are not numbers.
        case(
            "mass is a string",
            free("mass = 1.0", "mass = \"two\" # <--"),
            "body.mass",
            &["string"],
        ),
        case(
            "mass is nan",
            free("mass = 1.0", "mass = nan # <--"),
            "body.mass",
            &["NaN"],
        ),
        case(
            "mass is inf",
            free("mass = 1.0", "mass = inf # <--"),
            "body.mass",
            &["inf"],
        ),
        case(
            "t_end is inf",
            free("t_end = 1.0", "t_end = inf # <--"),
            "solver.t_end",
            &["inf"],
        ),
        case(
            "omega component nan",
            free("omega = [0.3, 0.0, 2.0]", "omega = [0.3, nan, 2.0] # <--"),
            "initial.omega",
            &["finite"],
        ),
        case(
            "omega so large that I·omega overflows",
            free(
                "omega = [0.3, 0.0, 2.0]",
                "omega = [1e200, 0.0, 1e200] # <--",
            ),
            "initial.omega",
            &["too large", "double precision"],
        ),
        case(
            "torque whose length overflows",
            free_plus("\n[[effect]]\ntype = \"torque\"\nvalue = [1e300, 0.0, 1e300] # <--\n"),
            "effect[0].value",
            &["too large", "double precision"],
        ),
        case(
            "gravity moment m|g||pivot| overflows",
            free_plus(
                "\n[[effect]]\ntype = \"gravity\"\ng = [0.0, 0.0, -1e200] # <--\npivot = [0.0, 0.0, 1e200]\n",
            ),
            "effect[0].g",
            &["too large", "double precision"],
        ),
        case(
            "rate so large that the bearing moment overflows",
            disk("rate = 10.0", "rate = 1e200 # <--"),
            "motion.rate",
            &["too large", "double precision"],
        ),
        case(
            "effect value has a string (the second effect)",
            free_plus(
                "\n[[effect]]\ntype = \"damping\"\nc = 0.1\n\n[[effect]]\ntype = \"damping\"\nc = \"x\" # <--\n",
            ),
            "effect[1].c",
            &["string"],
        ),
        case(
            "rate is a string",
            disk("rate = 10.0", "rate = \"fast\" # <--"),
            "motion.rate",
            &["string"],
        ),
        // Array lengths.
        case(
            "inertia with two moments",
            free("inertia = [1.0, 2.0, 3.0]", "inertia = [1, 2] # <--"),
            "body.inertia",
            &[],
        ),
        case(
            "inertia with four moments",
            free("inertia = [1.0, 2.0, 3.0]", "inertia = [1, 2, 3, 4] # <--"),
            "body.inertia",
            &[],
        ),
        case(
            "omega with four components",
            free("omega = [0.3, 0.0, 2.0]", "omega = [1, 2, 3, 4] # <--"),
            "initial.omega",
            &["length 4"],
        ),
        case(
            "omega with two components",
            free("omega = [0.3, 0.0, 2.0]", "omega = [1, 2] # <--"),
            "initial.omega",
            &["length 2"],
        ),
        case(
            "attitude with five components",
            free(
                "omega = [0.3, 0.0, 2.0]",
                "attitude = [1, 0, 0, 0, 0] # <--",
            ),
            "initial.attitude",
            &["length 5"],
        ),
        case(
            "box size with four edges",
            free(
                "inertia = [1.0, 2.0, 3.0]",
                "shape = { type = \"box\", size = [1, 2, 3, 4] } # <--",
            ),
            "body.shape.size",
            &["length 4"],
        ),
        case(
            "torque value with four components",
            free_plus("\n[[effect]]\ntype = \"torque\"\nvalue = [0, 0, 1, 0] # <--\n"),
            "effect[0].value",
            &["length 4"],
        ),
        // The body.
        case(
            "inertia not symmetric",
            free(
                "inertia = [1.0, 2.0, 3.0]",
                "inertia = [[1, 0.1, 0], [0, 1, 0], [0, 0, 1]] # <--",
            ),
            "body.inertia",
            &["symmetric"],
        ),
        case(
            "inertia not positive semi-definite",
            free(
                "inertia = [1.0, 2.0, 3.0]",
                "inertia = [[1, 0, 0], [0, 1, 0], [0, 0, -1]] # <--",
            ),
            "body.inertia",
            &["positive"],
        ),
        case(
            "triangle inequality violated",
            free("inertia = [1.0, 2.0, 3.0]", "inertia = [1, 1, 3] # <--"),
            "body.inertia",
            &["triangle"],
        ),
        case(
            "zero mass",
            free("mass = 1.0", "mass = 0 # <--"),
            "body.mass",
            &["> 0"],
        ),
        case(
            "negative mass",
            free("mass = 1.0", "mass = -1.0 # <--"),
            "body.mass",
            &["-1"],
        ),
        case(
            "both shape and inertia",
            free(
                "inertia = [1.0, 2.0, 3.0]",
                "shape = { type = \"sphere\", radius = 1.0 }\ninertia = [1.0, 2.0, 3.0] # <--",
            ),
            "body.inertia",
            &["not both"],
        ),
        case(
            "neither shape nor inertia",
            free(
                "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]",
                "[body] # <--\nmass = 1.0",
            ),
            "body",
            &["shape", "inertia"],
        ),
        case(
            "unknown shape type",
            free(
                "inertia = [1.0, 2.0, 3.0]",
                "shape = { type = \"cube\", radius = 1.0 } # <--",
            ),
            "body.shape.type",
            &["cube"],
        ),
        case(
            "negative shape radius",
            free(
                "inertia = [1.0, 2.0, 3.0]",
                "shape = { type = \"sphere\", radius = -1.0 } # <--",
            ),
            "body.shape.radius",
            &["> 0"],
        ),
        case(
            "thin rod in free motion",
            free(
                "inertia = [1.0, 2.0, 3.0]",
                "shape = { type = \"thin_rod\", length = 1.0 } # <--",
            ),
            "body.shape",
            &["zero principal moment"],
        ),
        // The motion.
        case(
            "zero axis vector",
            disk("tilt_deg = 30", "axis = [0.0, 0.0, 0.0] # <--"),
            "motion.axis",
            &["zero"],
        ),
        case(
            "both axis and tilt_deg",
            disk(
                "tilt_deg = 30",
                "axis = [0.0, 0.0, 1.0]\ntilt_deg = 30 # <--",
            ),
            "motion.tilt_deg",
            &["not both"],
        ),
        case(
            "neither axis nor tilt_deg",
            disk(
                "[motion]\ntype = \"fixed_axis\"\ntilt_deg = 30",
                "[motion] # <--\ntype = \"fixed_axis\"",
            ),
            "motion",
            &["axis"],
        ),
        case(
            "unknown motion type",
            disk("type = \"fixed_axis\"", "type = \"wobble\" # <--"),
            "motion.type",
            &["wobble"],
        ),
        case(
            "initial omega with a fixed axis",
            format!("{}\n[initial]\nomega = [1.0, 0.0, 0.0] # <--\n", DISK_SCENE),
            "initial.omega",
            &["fixed-axis"],
        ),
        case(
            "effects with a fixed_axis motion",
            format!("{DISK_SCENE}\n[[effect]] # <--\ntype = \"damping\"\nc = 0.1\n"),
            "effect[0]",
            &["fixed-axis"],
        ),
        case(
            "zero quaternion attitude",
            free(
                "omega = [0.3, 0.0, 2.0]",
                "attitude = [0.0, 0.0, 0.0, 0.0] # <--",
            ),
            "initial.attitude",
            &["zero quaternion"],
        ),
        // Effects.
        case(
            "negative damping",
            free_plus("\n[[effect]]\ntype = \"damping\"\nc = -0.1 # <--\n"),
            "effect[0].c",
            &[">= 0"],
        ),
        case(
            "step torque with t_off before t_on",
            free_plus(
                "\n[[effect]]\ntype = \"torque\"\nvalue = [0.0, 0.0, 1.0]\nprofile = \"step\"\nt_on = 1.0\nt_off = 0.5 # <--\n",
            ),
            "effect[0].t_off",
            &["t_on"],
        ),
        case(
            "step torque with t_off equal to t_on",
            free_plus(
                "\n[[effect]]\ntype = \"torque\"\nvalue = [0.0, 0.0, 1.0]\nprofile = \"step\"\nt_on = 1.0\nt_off = 1.0 # <--\n",
            ),
            "effect[0].t_off",
            &["t_on"],
        ),
        case(
            "sine torque without a frequency",
            free_plus(
                "\n[[effect]] # <--\ntype = \"torque\"\nvalue = [0.0, 0.0, 1.0]\nprofile = \"sine\"\n",
            ),
            "effect[0].freq_hz",
            &["freq_hz"],
        ),
        case(
            "unknown effect type",
            free_plus("\n[[effect]]\ntype = \"spring\" # <--\n"),
            "effect[0].type",
            &["spring"],
        ),
        case(
            "two gravity effects",
            free_plus(
                "\n[[effect]]\ntype = \"gravity\"\npivot = [0, 0, -0.1]\n\n[[effect]] # <--\ntype = \"gravity\"\npivot = [0, 0, 0.1]\n",
            ),
            "effect[1]",
            &["gravity"],
        ),
        // The solver and the output.
        case(
            "dt zero",
            free("t_end = 1.0", "t_end = 1.0\ndt = 0.0 # <--"),
            "solver.dt",
            &["> 0"],
        ),
        case(
            "dt negative",
            free(
                "t_end = 1.0",
                "t_end = 1.0\nmethod = \"rk4\"\ndt = -1e-3 # <--",
            ),
            "solver.dt",
            &["> 0"],
        ),
        case(
            "every zero",
            free("every = 0.1", "every = 0.0 # <--"),
            "output.every",
            &["> 0"],
        ),
        case(
            "every negative",
            free("every = 0.1", "every = -0.1 # <--"),
            "output.every",
            &["> 0"],
        ),
        case(
            "t_end negative",
            free("t_end = 1.0", "t_end = -1.0 # <--"),
            "solver.t_end",
            &[">= 0"],
        ),
        case(
            "every longer than t_end",
            free("every = 0.1", "every = 2.0 # <--"),
            "output.every",
            &["t_end"],
        ),
        case(
            "too many rows",
            free("every = 0.1", "every = 1e-9 # <--").replace("t_end = 1.0", "t_end = 1e3"),
            "output.every",
            &["rows"],
        ),
        case(
            "too many fixed steps",
            free(
                "t_end = 1.0",
                "t_end = 1e3\nmethod = \"rk4\"\ndt = 1e-10 # <--",
            ),
            "solver.dt",
            &["steps"],
        ),
        case(
            "the exact method with an effect it cannot do",
            free_plus("\n[[effect]]\ntype = \"torque\"\nvalue = [0.0, 0.0, 0.1]\n")
                .replace("t_end = 1.0", "t_end = 1.0\nmethod = \"exact\" # <--"),
            "solver.method",
            &["exact", "effect[0]", "torque"],
        ),
        case(
            "a project method through the ode_solvers backend",
            free(
                "t_end = 1.0",
                "t_end = 1.0\nmethod = \"split2\"\nbackend = \"ode_solvers\" # <--",
            ),
            "solver.backend",
            &["split2"],
        ),
        case(
            "unknown method",
            free("t_end = 1.0", "t_end = 1.0\nmethod = \"euler\" # <--"),
            "solver.method",
            &["euler", "rk4"],
        ),
        case(
            "unknown frame",
            free("t_end = 1.0", "t_end = 1.0\nframe = \"up\" # <--"),
            "solver.frame",
            &["up", "body", "space"],
        ),
        case(
            "unknown backend",
            free("t_end = 1.0", "t_end = 1.0\nbackend = \"scipy\" # <--"),
            "solver.backend",
            &["scipy"],
        ),
        case(
            "rtol zero",
            free("t_end = 1.0", "t_end = 1.0\nrtol = 0.0 # <--"),
            "solver.rtol",
            &[],
        ),
        case(
            "atol negative",
            free("t_end = 1.0", "t_end = 1.0\natol = -1e-12 # <--"),
            "solver.atol",
            &["> 0"],
        ),
        case(
            "compare tolerance zero",
            free_plus("\n[compare]\ntolerance = 0.0 # <--\n"),
            "compare.tolerance",
            &["> 0"],
        ),
        // Bad values on the command line.
        flag("--dt negative", &["--dt", "-1"], "solver.dt"),
        flag(
            "--dt zero with rk4",
            &["--dt", "0", "--method", "rk4"],
            "solver.dt",
        ),
        flag("--every zero", &["--every", "0"], "output.every"),
        flag("--every negative", &["--every", "-0.5"], "output.every"),
        flag(
            "--every longer than t_end",
            &["--every", "5"],
            "output.every",
        ),
        flag("--t-end negative", &["--t-end", "-1"], "solver.t_end"),
        flag("--t-end inf", &["--t-end", "inf"], "solver.t_end"),
        flag("--method unknown", &["--method", "foo"], "solver.method"),
        flag("--frame unknown", &["--frame", "up"], "solver.frame"),
        flag(
            "--backend unknown",
            &["--backend", "scipy"],
            "solver.backend",
        ),
        flag("--rtol too large", &["--rtol", "2"], "solver.rtol"),
        flag("--rtol nan", &["--rtol", "nan"], "solver.rtol"),
        flag("--atol zero", &["--atol", "0"], "solver.atol"),
    ];
    // A flag whose value is not a number at all: the argument parser refuses it (exit 2), naming the flag.
    cases.push(Case {
        names_file: false,
        expect: vec!["--dt".into(), "abc".into()],
        ..flag("--dt not a number", &["--dt", "abc"], "")
    });
    cases
}

/// Runs one case through `check` and `run -o`; returns what went wrong.
fn run_case(case: &Case) -> Vec<String> {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let scene: PathBuf = match &case.input {
        Input::Text(text) => write_file(dir.path(), "scene.toml", text),
        Input::Bytes(bytes) => write_file(dir.path(), "scene.toml", bytes),
        Input::Directory => {
            let path = dir.path().join("scenes.toml");
            std::fs::create_dir(&path).expect("a directory");
            path
        }
        Input::Missing => dir.path().join("missing.toml"),
    };
    let scene_text = scene.to_str().expect("a UTF-8 path");
    let out_path = dir.path().join("out.csv");
    let before = dir_entries(dir.path());

    let mut commands: Vec<(&str, Vec<&str>)> = Vec::new();
    if case.flags.is_empty() {
        commands.push(("check", vec!["check", scene_text]));
    }
    let mut run = vec![
        "run",
        scene_text,
        "-o",
        out_path.to_str().expect("a UTF-8 path"),
    ];
    run.extend(&case.flags);
    commands.push(("run -o", run));

    let mut problems = Vec::new();
    for (command, args) in commands {
        let out = eulerdyn(&args);
        let mut fail = |what: String| {
            problems.push(format!(
                "[{}] `{command}`: {what}\n    stderr: {}",
                case.name,
                out.stderr.trim_end()
            ));
        };
        if out.panicked() {
            fail("panicked".into());
        }
        if out.code != Some(2) {
            fail(format!("exit code {:?}, want 2", out.code));
        }
        if !out.stdout.is_empty() {
            fail(format!("wrote to stdout: {:?}", out.stdout));
        }
        if !out.stderr.starts_with("error: ") {
            fail("the message does not start with `error: `".into());
        }
        if case.names_file && !out.stderr.contains(scene_text) {
            fail(format!("the message does not name the file {scene_text}"));
        }
        for want in &case.expect {
            if !out.stderr.contains(want.as_str()) {
                fail(format!("the message lacks {want:?}"));
            }
        }
        if let Some(line) = case.line {
            let at = format!("{scene_text}:{line}:");
            if !out.stderr.contains(&at) {
                fail(format!("the message does not give line {line} ({at})"));
            }
        }
        if out.stderr.lines().count() > 3 {
            fail("the message is longer than 3 lines".into());
        }
    }
    let after = dir_entries(dir.path());
    if after != before {
        problems.push(format!(
            "[{}] files were left behind: {before:?} -> {after:?}",
            case.name
        ));
    }
    problems
}

#[test]
fn every_bad_scene_is_refused_with_its_key_and_line() {
    let cases = cases();
    assert!(cases.len() > 80);
    let problems: Vec<String> = cases.iter().flat_map(run_case).collect();
    assert!(
        problems.is_empty(),
        "{} problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn case_names_are_unique() {
    let cases = cases();
    let mut names: Vec<&str> = cases.iter().map(|c| c.name).collect();
    names.sort_unstable();
    let before = names.len();
    names.dedup();
    assert_eq!(names.len(), before, "duplicate case names");
}

/// The boundary the corpus must not cross: t_end = 0 is valid and gives one row.
#[test]
fn t_end_zero_is_valid() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(dir.path(), "zero.toml", free("t_end = 1.0", "t_end = 0.0"));
    let scene = scene.to_str().unwrap();
    let out = eulerdyn(["check", scene]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let out = eulerdyn(["run", scene]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let (_, records) = read_csv(&out.stdout);
    assert_eq!(records.len(), 1);
    assert_eq!(&records[0][0], "0.0");
}

/// The bases of the corpus are themselves valid, so each case fails for its own edit only.
#[test]
fn the_base_scenes_are_valid() {
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in [("free.toml", FREE_SCENE), ("disk.toml", DISK_SCENE)] {
        let path: &Path = &write_file(dir.path(), name, text);
        let out = eulerdyn(["check", path.to_str().unwrap()]);
        assert_eq!(out.code, Some(0), "{name}: {}", out.stderr);
    }
}
