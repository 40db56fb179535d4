//! Unit tests of the plan format: ranges, grid and zip, ids, flags, defaults.
use super::plan::{Plan, PlanError};
use super::values::{Scale, Value};
use crate::cli::CommandLineCases;

/// A plan's text parsed against this command line's case options.
fn parse(text: &str, stem: &str) -> Result<Plan, PlanError> {
    super::plan::parse(text, stem, &CommandLineCases)
}

fn args_of(plan: &str) -> Vec<Vec<String>> {
    let p = parse(plan, "t").expect("plan parses");
    p.cases().into_iter().map(|c| c.args).collect()
}

fn floats(vs: &[Value]) -> Vec<f64> {
    vs.iter().map(|v| v.as_f64().unwrap()).collect()
}

#[test]
fn linear_and_log_ranges_hit_their_ends_exactly() {
    let p = parse(
        "case = \"static\"\n[grid]\nalpha = { from = 0, to = 1, count = 5 }\n\
         re = { from = 100, to = 10000, count = 3, scale = \"log\" }\n\
         resolution = { from = 16, to = 64, count = 3, scale = \"log\" }\n",
        "t",
    )
    .unwrap();
    assert_eq!(floats(&p.grid[0].values), [0.0, 0.25, 0.5, 0.75, 1.0]);
    assert_eq!(floats(&p.grid[1].values), [100.0, 1000.0, 10000.0]);
    assert_eq!(p.grid[1].scale, Scale::Log);
    // 16·(64/16)^(1/2) in floating point is not exactly 32; the plan writes 32.
    assert_eq!(p.grid[2].values[1].arg(), "32");
    let single = parse(
        "case = \"static\"\n[grid]\nalpha = { from = 0.3, to = 9, count = 1 }\n",
        "t",
    );
    assert_eq!(floats(&single.unwrap().grid[0].values), [0.3]);
}

#[test]
fn a_grid_varies_its_first_option_slowest() {
    let cases = parse(
        "case = \"static\"\n[grid]\nalpha = [0.1, 0.2]\nre = [100, 200, 300]\n",
        "t",
    )
    .unwrap()
    .cases();
    let ids: Vec<&str> = cases.iter().map(|c| c.id.as_str()).collect();
    assert_eq!(
        ids,
        [
            "0000-alpha=0.1-re=100",
            "0001-alpha=0.1-re=200",
            "0002-alpha=0.1-re=300",
            "0003-alpha=0.2-re=100",
            "0004-alpha=0.2-re=200",
            "0005-alpha=0.2-re=300",
        ]
    );
    assert_eq!(cases[4].args, ["static", "--alpha=0.2", "--re=200"]);
}

#[test]
fn zipped_options_advance_together_inside_the_grid() {
    let plan = "case = \"free\"\n[fixed]\nresolution = 16\n[grid]\nre = [1000, 2000]\n\
                [zip]\nmass = [0.3, 1, 2]\ninertia = [0.01, 0.05, 0.1]\n";
    let p = parse(plan, "t").unwrap();
    assert_eq!(p.case_count(), 6);
    let cases = p.cases();
    assert_eq!(cases[3].id, "0003-re=2000-mass=0.3-inertia=0.01");
    assert_eq!(
        cases[2].args,
        [
            "free",
            "--resolution=16",
            "--re=1000",
            "--mass=2",
            "--inertia=0.1"
        ]
    );
    // The same plan gives the same ids and arguments every time.
    assert_eq!(parse(plan, "t").unwrap().cases(), cases);
    let zip_only = parse(
        "case = \"free\"\n[zip]\nmass = [1, 2]\ninertia = [0.1, 0.2]\n",
        "t",
    );
    assert_eq!(zip_only.unwrap().case_count(), 2);
}

#[test]
fn flags_text_and_negative_values_become_arguments() {
    let args = args_of(
        "case = \"pinned\"\n[fixed]\nseed-grid = true\nab_start = \"extrapolate\"\n\
         [grid]\nalpha0 = [-0.4]\npreset = [\"card\"]\n",
    );
    assert_eq!(
        args[0],
        [
            "pinned",
            "--seed-grid",
            "--ab-start=extrapolate",
            "--alpha0=-0.4",
            "--preset=card"
        ]
    );
    assert!(super::options::CaseCommands::config(&CommandLineCases, &args[0]).is_ok());
    let flags = args_of("case = \"static\"\n[grid]\nseed-grid = [true, false]\n");
    assert_eq!(flags, [vec!["static", "--seed-grid"], vec!["static"]]);
}

#[test]
fn ids_are_safe_file_names_and_wide_enough() {
    let p = parse(
        "case = \"static\"\n[grid]\nfield-window = [\"-2,4,-2,2\"]\nkick = { from = 0, to = 0.1, count = 10001 }\n",
        "t",
    )
    .unwrap();
    let cases = p.cases();
    assert_eq!(cases[0].id, "00000-field-window=-2_4_-2_2-kick=0");
    assert_eq!(cases[10000].id, "10000-field-window=-2_4_-2_2-kick=0.1");
}

#[test]
fn the_diagram_defaults_to_the_first_two_swept_options() {
    let p = parse(
        "case = \"free\"\n[grid]\nre = { from = 100, to = 1000, count = 2, scale = \"log\" }\n\
         inertia = [0.1, 0.2]\n",
        "t",
    )
    .unwrap();
    assert_eq!(p.diagram.x, "re");
    assert_eq!(p.diagram.y.as_deref(), Some("inertia"));
    assert_eq!(p.diagram.value, "mean_omega");
    assert_eq!(
        (p.diagram.x_scale, p.diagram.y_scale),
        (Scale::Log, Scale::Linear)
    );
    let one = parse("case = \"static\"\n[grid]\nalpha = [0.1]\n", "t").unwrap();
    assert_eq!(
        (one.diagram.y, one.diagram.value.as_str()),
        (None, "mean_cl")
    );
    assert_eq!(one.name, "t");
    let strip = parse(
        "case = \"static\"\n[grid]\nalpha = [0.1]\nre = [100]\n[diagram]\ny = \"\"\n",
        "t",
    );
    assert_eq!(strip.unwrap().diagram.y, None);
}

#[test]
fn plan_errors_name_the_value_and_what_is_accepted() {
    let err = |body: &str| parse(body, "t").unwrap_err().0;
    assert!(
        err("case = \"static\"\n[grid]\nre = { from = 1, to = 2 }\n")
            .contains("missing field `count`")
    );
    assert!(err(
        "case = \"static\"\n[grid]\nre = { from = 1, to = 2, count = 2, scale = \"cubic\" }\n"
    )
    .contains("cubic"));
    assert!(err("case = \"static\"\n[grid]\nalpha = 0.4\n").contains("takes a list"));
    assert!(err("case = \"static\"\n[fixed]\nalpha = [0.4]\n").contains("one value per option"));
    assert!(
        err("case = \"static\"\n[grid]\nalpha = [0.1]\n[diagram]\ny = \"alpha\"\n")
            .contains("both \"alpha\"")
    );
}
