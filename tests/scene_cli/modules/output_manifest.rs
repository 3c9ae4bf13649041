//! The items of `src/output/manifest.rs`.

use pegdyn::output::manifest::*;
use std::path::PathBuf;

fn sample() -> Manifest {
    Manifest {
        scene: "scenes/s.toml".into(),
        scene_hash: format!("fnv1a64:{}", fnv1a64(b"kind = \"pendulum\"")),
        command: "pegdyn run \"scenes/s.toml\"".into(),
        out: "out".into(),
        lossy: vec!["out"],
        pid: 77,
        started: "2026-01-02T03:04:05Z".into(),
        status: "running".into(),
        ended: None,
        files: vec![],
        stale: vec![PathBuf::from("out/s.old.svg")],
    }
}

#[test]
fn a_manifest_round_trips_and_is_recognized() {
    let dir = std::env::temp_dir().join(format!("pegdyn-manifest-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("s.run.toml");
    let mut m = sample();
    std::fs::write(&path, m.to_toml()).unwrap();
    let parsed: toml::Table = m.to_toml().parse().unwrap();
    assert_eq!(parsed["status"].as_str(), Some("running"));
    assert_eq!(parsed["pid"].as_integer(), Some(77));
    assert_eq!(parsed["lossy"][0].as_str(), Some("out"));
    assert_eq!(parsed["stale"][0].as_str(), Some("s.old.svg"));
    assert!(parsed.get("ended").is_none());
    assert_eq!(
        existing(&path),
        Existing::Manifest {
            running: Some((77, "2026-01-02T03:04:05Z".into()))
        }
    );
    m.status = "ok".into();
    m.ended = Some("2026-01-02T03:04:06Z".into());
    std::fs::write(&path, m.to_toml()).unwrap();
    assert_eq!(existing(&path), Existing::Manifest { running: None });
    // The format written before `pegdyn_manifest` existed.
    std::fs::write(
        &path,
        "scene = \"a\"\nscene_hash = \"fnv1a64:0\"\npegdyn_version = \"0.1.0\"\nstatus = \"ok\"\n",
    )
    .unwrap();
    assert_eq!(existing(&path), Existing::Manifest { running: None });
    for foreign in [
        "[tool]\nname = \"mine\"\n",
        "not toml at all",
        "status = \"ok\"\n",
    ] {
        std::fs::write(&path, foreign).unwrap();
        assert_eq!(existing(&path), Existing::Foreign, "{foreign}");
    }
    std::fs::remove_file(&path).unwrap();
    assert_eq!(existing(&path), Existing::None);
    std::fs::create_dir(&path).unwrap();
    assert_eq!(existing(&path), Existing::Foreign);
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(fnv1a64(b""), "cbf29ce484222325");
}

#[test]
fn stale_files_are_only_this_scenes() {
    let dir = std::env::temp_dir().join(format!("pegdyn-stale-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for f in [
        "s.csv",
        "s.old.svg",
        "s.run.toml",
        "s_rcc.csv",
        "other.csv",
        ".s.csv.tmp-1",
    ] {
        std::fs::write(dir.join(f), "").unwrap();
    }
    let stale = stale_files(&dir, "s", &[dir.join("s.csv")]);
    assert_eq!(stale, vec![dir.join("s.old.svg")]);
    std::fs::remove_dir_all(&dir).unwrap();
}
