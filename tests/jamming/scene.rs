//! The `jamming` scene: `scenes/jamming.toml` writes the corner table with
//! exactly the promised columns (no exact rows where two-point contact is
//! impossible), the wedging table and the SVG; bad values are refused with
//! the field's dotted path.

use std::path::PathBuf;

use pegdyn::jamming::sensitivities::sensitivities;
use pegdyn::jamming::{PegHole, diagram, wedging};
use pegdyn::output::sink::Sink;
use pegdyn::scene::{self, Progress, RunContext};

fn out_dir(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pegdyn-jam-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn read_csv(path: &std::path::Path) -> (String, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap().to_string();
    let rows = lines
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    (header, rows)
}

#[test]
fn scene_file_writes_corners_wedging_and_svg() {
    // the analytic part of scenes/jamming.toml (its [sweep] is tested in
    // tests/jamming/dynamic.rs on a coarser grid)
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/jamming.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let analytic = text.split("[sweep]").next().unwrap();
    assert!(text.contains("[sweep]"));
    let loaded = scene::parse_named(analytic, "jamming").unwrap();
    let dir = out_dir("scene");
    let sink = Sink::directory(&dir, &loaded.name);
    let mut ctx = RunContext::new(sink, Progress::silent());
    loaded.run(&mut ctx).unwrap();

    let (header, rows) = read_csv(&dir.join("jamming.corners.csv"));
    assert_eq!(header, "l_m,c,mu,kind,fx_over_fz,m_over_rfz");
    // 2 c × 2 μ × (3 Whitney + 2 exact: l = 1 mm is too shallow) × 4 corners
    assert_eq!(rows.len(), 2 * 2 * 5 * 4);
    let num = |s: &str| s.parse::<f64>().unwrap();
    for row in &rows {
        let (l, c, mu) = (num(&row[0]), num(&row[1]), num(&row[2]));
        let p = PegHole::try_new(0.0125, c, mu).unwrap();
        let g = match row[3].as_str() {
            "whitney" => diagram::whitney_parallelogram(&p, l).unwrap(),
            "exact" => diagram::exact_parallelogram(&p, l).unwrap().unwrap(),
            other => panic!("kind {other}"),
        };
        let q = [num(&row[4]), num(&row[5])];
        assert!(g.corners.contains(&q), "{row:?}");
        assert!(!(row[3] == "exact" && l == 0.001), "{row:?}");
    }

    let (header, rows) = read_csv(&dir.join("jamming.wedging.csv"));
    assert_eq!(header, "c,mu,theta_wedge_rad");
    assert_eq!(rows.len(), 4);
    for row in &rows {
        let p = PegHole::try_new(0.0125, num(&row[0]), num(&row[1])).unwrap();
        match wedging::wedging_angle(&p) {
            Some(th) => assert_eq!(num(&row[2]), th),
            None => assert_eq!(row[2], "inf"),
        }
    }
    let svg = std::fs::read_to_string(dir.join("jamming.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("c = 0.01, mu = 0.3"));

    let (header, rows) = read_csv(&dir.join("jamming.sensitivities.csv"));
    assert_eq!(header, "l_m,c,mu,kind,quantity,value,d_dr,d_dc,d_dmu,d_dl");
    // 2 c × 2 μ × (3 Whitney + 2 exact) × 7 quantities, then per (c, μ)
    // the series and Whitney's wedging angle and the exact one where it
    // exists (not at c = 0.01, μ = 0.1).
    assert_eq!(rows.len(), 2 * 2 * 5 * 7 + 4 * 2 + 3);
    for row in &rows {
        let (c, mu) = (num(&row[1]), num(&row[2]));
        let p = PegHole::try_new(0.0125, c, mu).unwrap();
        let got: Vec<f64> = row[5..].iter().map(|v| num(v)).collect();
        let (value, g) = if row[3] == "wedging" {
            assert_eq!(row[0], "");
            let s = sensitivities(&p, 0.01).unwrap().wedging;
            match row[4].as_str() {
                "theta_exact_rad" => (wedging::wedging_angle(&p).unwrap(), s.exact.unwrap()),
                "theta_series_rad" => (wedging::wedging_angle_series(&p), s.series),
                "theta_whitney_rad" => (wedging::wedging_angle_whitney(&p), s.whitney),
                other => panic!("quantity {other}"),
            }
        } else {
            let l = num(&row[0]);
            let s = sensitivities(&p, l).unwrap();
            let (g, d) = match row[3].as_str() {
                "whitney" => (diagram::whitney_parallelogram(&p, l).unwrap(), s.whitney),
                "exact" => (
                    diagram::exact_parallelogram(&p, l).unwrap().unwrap(),
                    s.exact.unwrap(),
                ),
                other => panic!("kind {other}"),
            };
            let (slope, intercept) = g.two_point_line();
            match row[4].as_str() {
                "p1_fx_over_fz" => (g.corners[2][0], d.edge_corner.force_ratio),
                "p1_m_over_rfz" => (g.corners[2][1], d.edge_corner.moment_ratio),
                "q_fx_over_fz" => (g.corners[1][0], d.mirrored_corner.force_ratio),
                "q_m_over_rfz" => (g.corners[1][1], d.mirrored_corner.moment_ratio),
                "slope" => (slope, d.slope),
                "intercept" => (intercept, d.intercept),
                "tilt_rad" => (g.theta, d.tilt),
                other => panic!("quantity {other}"),
            }
        };
        assert_eq!(got, [value, g.r, g.c, g.mu, g.l], "{row:?}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

fn refusal(table: &str) -> String {
    let text = format!("kind = \"jamming\"\n[jamming]\n{table}\n");
    scene::parse(&text).unwrap_err().to_string()
}

#[test]
fn bad_values_are_refused_with_their_field() {
    let ok = "r_m = 0.0125\nc = [0.01]\nmu = [0.3]\nl_m = [0.005]";
    assert!(scene::parse(&format!("kind = \"jamming\"\n[jamming]\n{ok}\n")).is_ok());
    let cases = [
        (
            "r_m = 0.0\nc = [0.01]\nmu = [0.3]\nl_m = [0.005]",
            "jamming.r_m",
        ),
        (
            "r_m = nan\nc = [0.01]\nmu = [0.3]\nl_m = [0.005]",
            "jamming.r_m",
        ),
        (
            "r_m = 0.0125\nc = [0.01, 1.5]\nmu = [0.3]\nl_m = [0.005]",
            "jamming.c[1]",
        ),
        (
            "r_m = 0.0125\nc = [0.0]\nmu = [0.3]\nl_m = [0.005]",
            "jamming.c[0]",
        ),
        (
            "r_m = 0.0125\nc = [0.01]\nmu = [0.3, -0.1]\nl_m = [0.005]",
            "jamming.mu[1]",
        ),
        (
            "r_m = 0.0125\nc = [0.01]\nmu = [nan]\nl_m = [0.005]",
            "jamming.mu[0]",
        ),
        (
            "r_m = 0.0125\nc = [0.01]\nmu = [0.3]\nl_m = [-1.0]",
            "jamming.l_m[0]",
        ),
        (
            "r_m = 0.0125\nc = []\nmu = [0.3]\nl_m = [0.005]",
            "jamming.c",
        ),
    ];
    for (table, field) in cases {
        let e = refusal(table);
        assert!(e.contains(&format!("`{field}`")), "{field}: {e}");
    }
}
