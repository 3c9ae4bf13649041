//! A run's record tells the truth, and its files are its own: the manifest
//! says `running` (process, start) before any output is replaced; SIGTERM
//! and SIGINT stop the run and record `interrupted`; a run killed with
//! SIGKILL is reported, and its partial files removed, by the next run; the
//! hash is of the text that was parsed; paths that are not UTF-8 are
//! recorded lossily, marked; no two scenes' files share a name, a
//! manifest lists only its own scene's files, and a user's file with a
//! manifest's name is never replaced.

use crate::common::scene_text::shipped;
use std::path::{Path, PathBuf};
use std::process::Child;
use std::time::{Duration, Instant};

use crate::common::cli::{fresh_dir, pegdyn, pegdyn_os, spawn_pegdyn};

/// The shipped scene `name` with `from` replaced by `to` (must occur).
fn variant(name: &str, from: &str, to: &str) -> String {
    let text = shipped(name);
    assert!(text.contains(from), "{name} has no {from:?}");
    text.replacen(from, to, 1)
}

fn manifest(path: &Path) -> Option<toml::Table> {
    std::fs::read_to_string(path).ok()?.parse().ok()
}

fn strings(m: &toml::Table, key: &str) -> Vec<String> {
    m[key]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap().to_owned())
        .collect()
}

/// Waits (at most a minute) until `ready` holds, or the child exits.
fn wait_for(child: &mut Child, what: &str, mut ready: impl FnMut() -> bool) {
    let t = Instant::now();
    while !ready() {
        if let Ok(Some(status)) = child.try_wait() {
            panic!("the run ended ({status}) before {what}");
        }
        assert!(t.elapsed() < Duration::from_secs(60), "no {what}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Long runs of several kinds: a streamed time series (pendulum), a
/// stored 3-D insertion, a parallel grid of insertions.
fn long_scenes() -> Vec<(&'static str, String, Vec<&'static str>)> {
    vec![
        (
            "swing",
            variant("pendulum", "t_end = 10.0", "t_end = 1e5"),
            vec!["--limit", "samples=1e8", "--limit", "memory_mb=1e6"],
        ),
        (
            "insert",
            variant("insert_rcc", "t_end = ", "t_end = 1e3 # ").replacen(
                "output_interval = ",
                "output_interval = 1e-3 # ",
                1,
            ),
            vec!["--limit", "samples=1e7", "--limit", "memory_mb=1e5"],
        ),
        (
            "grid",
            variant("rotation_assist", "t_end = ", "t_end = 1e3 # ").replacen(
                "output_interval = ",
                "output_interval = 1e-3 # ",
                1,
            ),
            vec!["--limit", "samples=1e7", "--limit", "memory_mb=1e5"],
        ),
    ]
}

fn start(dir: &Path, name: &str, text: &str, extra: &[&str]) -> (Child, PathBuf) {
    let scene = dir.join(format!("{name}.toml"));
    std::fs::write(&scene, text).unwrap();
    let out = dir.join("out");
    let mut args = vec![
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "-q",
    ];
    args.extend(extra);
    (spawn_pegdyn(&args), out.join(format!("{name}.run.toml")))
}

fn running_as(path: &Path, pid: u32) -> bool {
    manifest(path).is_some_and(|m| {
        m.get("status").and_then(|s| s.as_str()) == Some("running")
            && m.get("pid").and_then(|p| p.as_integer()) == Some(i64::from(pid))
    })
}

#[test]
fn sigterm_and_sigint_stop_the_run_and_record_interrupted() {
    for (signal, code) in [("TERM", 143), ("INT", 130)] {
        for (name, text, extra) in long_scenes() {
            let d = fresh_dir("record", &format!("signal-{signal}-{name}"));
            let (mut child, path) = start(&d, name, &text, &extra);
            let pid = child.id();
            wait_for(&mut child, "a running manifest", || running_as(&path, pid));
            let m = manifest(&path).unwrap();
            assert!(m["started"].as_str().unwrap().ends_with('Z'));
            assert!(m.get("ended").is_none());
            let kill = std::process::Command::new("kill")
                .args([format!("-{signal}"), pid.to_string()])
                .status()
                .unwrap();
            assert!(kill.success());
            let out = child.wait_with_output().unwrap();
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(code), "{name}: {stderr}");
            let m = manifest(&path).unwrap();
            assert_eq!(
                m["status"].as_str(),
                Some(format!("interrupted: SIG{signal}").as_str()),
                "{name}"
            );
            assert!(m["ended"].as_str().is_some());
            // Nothing half-written is left, and no file is claimed.
            let left: Vec<String> = std::fs::read_dir(d.join("out"))
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .collect();
            assert!(left.iter().all(|f| !f.starts_with('.')), "{left:?}");
            for f in strings(&m, "files") {
                assert!(left.contains(&f), "{name}: {f} listed, not present");
            }
        }
    }
}

#[test]
fn a_killed_run_is_reported_and_its_partial_files_removed_by_the_next() {
    let d = fresh_dir("record", "kill9");
    let (name, text, extra) = long_scenes().swap_remove(0);
    // An earlier, complete run: its table must stay until replaced whole.
    let short = variant("pendulum", "t_end = 10.0", "t_end = 0.5");
    let scene = d.join(format!("{name}.toml"));
    std::fs::write(&scene, &short).unwrap();
    let out = d.join("out");
    let first = pegdyn(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(first.status.success());
    let before = std::fs::read(out.join("swing.csv")).unwrap();
    let (mut child, path) = start(&d, name, &text, &extra);
    let pid = child.id();
    let tmp = out.join(format!(".swing.csv.tmp-{pid}"));
    wait_for(&mut child, "the streamed temporary file", || tmp.exists());
    assert!(running_as(&path, pid));
    // The previous table is untouched while the new one is written.
    assert_eq!(std::fs::read(out.join("swing.csv")).unwrap(), before);
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(running_as(&path, pid), "kill -9 leaves `running`");
    assert!(tmp.exists());
    // The next run reports the dead one and removes what it left.
    std::fs::write(&scene, &short).unwrap();
    let next = pegdyn(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&next.stderr);
    assert!(next.status.success(), "{stderr}");
    assert!(
        stderr.contains(&format!("process {pid}")) && stderr.contains("did not finish"),
        "{stderr}"
    );
    assert!(
        stderr.contains(&format!(".swing.csv.tmp-{pid}")),
        "{stderr}"
    );
    assert!(!tmp.exists());
    let m = manifest(&path).unwrap();
    assert_eq!(m["status"].as_str(), Some("ok"));
}

#[test]
fn the_manifest_hashes_the_text_that_was_parsed() {
    let d = fresh_dir("record", "hash");
    let (name, text, extra) = long_scenes().swap_remove(0);
    let (mut child, path) = start(&d, name, &text, &extra);
    let pid = child.id();
    wait_for(&mut child, "a running manifest", || running_as(&path, pid));
    // The scene is edited while it runs.
    let edited = text.replace("t_end = 1e5", "t_end = 2.0");
    std::fs::write(d.join(format!("{name}.toml")), &edited).unwrap();
    std::process::Command::new("kill")
        .args(["-TERM", &pid.to_string()])
        .status()
        .unwrap();
    child.wait().unwrap();
    let hash = |t: &str| {
        format!(
            "fnv1a64:{}",
            pegdyn::output::manifest::fnv1a64(t.as_bytes())
        )
    };
    let m = manifest(&path).unwrap();
    assert_eq!(m["scene_hash"].as_str(), Some(hash(&text).as_str()));
    assert_ne!(hash(&text), hash(&edited));
}

#[cfg(unix)]
#[test]
fn paths_that_are_not_utf8_run_and_are_recorded_lossily() {
    use std::ffi::OsStr;
    use std::os::unix::ffi::OsStrExt;
    let d = fresh_dir("record", "non-utf8");
    let text = variant("pendulum", "t_end = 10.0", "t_end = 0.2");
    let plain_dir = d.join("scenes");
    let odd_dir = d.join(OsStr::from_bytes(b"sc\xffenes"));
    for dir in [&plain_dir, &odd_dir] {
        std::fs::create_dir_all(dir).unwrap();
    }
    // (scene path, out dir, fields marked lossy)
    let cases: [(PathBuf, PathBuf, &[&str]); 4] = [
        (
            plain_dir.join(OsStr::from_bytes(b"sw\xfeing.toml")),
            d.join("out1"),
            &["command", "scene"],
        ),
        (
            plain_dir.join("swing.toml"),
            d.join(OsStr::from_bytes(b"out\xff2")),
            &["command", "out"],
        ),
        (
            odd_dir.join("swing.toml"),
            d.join(OsStr::from_bytes(b"o\x80ut3")),
            &["command", "out", "scene"],
        ),
        (plain_dir.join("swing.toml"), d.join("out4"), &[]),
    ];
    for (scene, out, lossy) in cases {
        std::fs::write(&scene, &text).unwrap();
        let check = pegdyn_os(&[OsStr::new("check"), scene.as_os_str()]);
        assert!(check.status.success(), "{scene:?}");
        let run = pegdyn_os(&[
            OsStr::new("run"),
            scene.as_os_str(),
            OsStr::new("--out"),
            out.as_os_str(),
        ]);
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert!(run.status.success(), "{scene:?} {out:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
        let stem = scene.file_stem().unwrap().to_string_lossy().into_owned();
        let m = manifest(&out.join(format!("{stem}.run.toml"))).unwrap();
        assert_eq!(m["status"].as_str(), Some("ok"));
        let mut marked = strings(&m, "lossy");
        marked.sort();
        assert_eq!(marked, lossy, "{scene:?} {out:?}");
        assert_eq!(strings(&m, "files").len(), 2);
        assert!(out.join(format!("{stem}.csv")).exists());
    }
}

/// Runs `scenes` (name, text) into one directory; returns each manifest.
fn run_all(dir: &Path, scenes: &[(&str, String)]) -> Vec<toml::Table> {
    let out = dir.join("out");
    scenes
        .iter()
        .map(|(name, text)| {
            let scene = dir.join(format!("{name}.toml"));
            std::fs::write(&scene, text).unwrap();
            let r = pegdyn(&[
                "run",
                scene.to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
            ]);
            assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
            manifest(&out.join(format!("{name}.run.toml"))).unwrap()
        })
        .collect()
}

#[test]
fn scenes_whose_output_names_collided_keep_their_own_files() {
    let jam = || variant("jamming", "n = 13", "n = 3");
    let pend = || variant("pendulum", "t_end = 10.0", "t_end = 0.3");
    // Each group once collided: a part of one scene's name is another's
    // suffix, or two scenes of a kind with fixed names.
    let groups: Vec<Vec<(&str, String)>> = vec![
        vec![("j", jam()), ("j_sweep", jam()), ("j_corners", jam())],
        vec![("jam_a", jam()), ("jam_b", jam())],
        vec![("p", pend()), ("p_events", pend()), ("p_run", pend())],
    ];
    for (g, scenes) in groups.iter().enumerate() {
        let d = fresh_dir("record", &format!("collide-{g}"));
        let manifests = run_all(&d, scenes);
        let mut all: Vec<String> = Vec::new();
        for ((name, _), m) in scenes.iter().zip(&manifests) {
            let files = strings(m, "files");
            assert!(!files.is_empty());
            for f in &files {
                assert!(f.starts_with(&format!("{name}.")), "{name}: {f}");
                assert!(!all.contains(f), "{f} written by two scenes");
            }
            assert_eq!(strings(m, "stale"), Vec::<String>::new(), "{name}");
            all.extend(files);
        }
        let on_disk = std::fs::read_dir(d.join("out")).unwrap().count();
        assert_eq!(on_disk, all.len() + scenes.len(), "files and manifests");
    }
}

#[test]
fn a_rerun_without_a_file_it_wrote_before_flags_it() {
    let d = fresh_dir("record", "rerun");
    let with = variant("jamming", "n = 13", "n = 3");
    let cut = with.find("[sweep]").unwrap();
    let without = with[..cut].to_owned();
    let first = run_all(&d, &[("j", with)]);
    assert!(strings(&first[0], "files").contains(&"j.sweep.csv".to_owned()));
    let second = run_all(&d, &[("j", without)]);
    assert_eq!(strings(&second[0], "stale"), ["j.sweep.csv", "j.sweep.svg"]);
    assert!(!strings(&second[0], "files").contains(&"j.sweep.csv".to_owned()));
}

#[test]
fn a_users_file_with_a_manifests_name_is_never_replaced() {
    let text = variant("pendulum", "t_end = 10.0", "t_end = 0.3");
    for (k, user) in [
        "my notes\n",
        "[tool.mine]\nname = \"x\"\n",
        "status = \"ok\"\nfiles = []\n",
        "",
    ]
    .iter()
    .enumerate()
    {
        let d = fresh_dir("record", &format!("foreign-{k}"));
        let out = d.join("out");
        std::fs::create_dir_all(&out).unwrap();
        std::fs::write(out.join("x.run.toml"), user).unwrap();
        let scene = d.join("x.toml");
        std::fs::write(&scene, &text).unwrap();
        let r = pegdyn(&[
            "run",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let stderr = String::from_utf8_lossy(&r.stderr);
        assert_eq!(r.status.code(), Some(1), "{stderr}");
        assert!(stderr.contains("not a pegdyn run manifest"), "{stderr}");
        assert_eq!(
            std::fs::read_to_string(out.join("x.run.toml")).unwrap(),
            *user
        );
        assert!(!out.join("x.csv").exists(), "nothing is written");
    }
    // A directory with that name is not replaced either.
    let d = fresh_dir("record", "foreign-dir");
    std::fs::create_dir_all(d.join("out/x.run.toml")).unwrap();
    let scene = d.join("x.toml");
    std::fs::write(&scene, &text).unwrap();
    let out = d.join("out");
    let r = pegdyn(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.status.code(), Some(1));
    assert!(d.join("out/x.run.toml").is_dir());
}

#[test]
fn scene_names_containing_the_separator_are_refused() {
    let d = fresh_dir("record", "dotted");
    let text = variant("pendulum", "t_end = 10.0", "t_end = 0.3");
    for name in ["v1.2", "x.run", "a.events", ".hidden"] {
        let scene = d.join(format!("{name}.toml"));
        std::fs::write(&scene, &text).unwrap();
        let out = d.join("out");
        let (s, o) = (scene.to_str().unwrap(), out.to_str().unwrap());
        for args in [vec!["check", s], vec!["run", s, "--out", o]] {
            let r = pegdyn(&args);
            let stderr = String::from_utf8_lossy(&r.stderr);
            assert_eq!(r.status.code(), Some(1), "{stderr}");
            assert!(stderr.contains("contains `.`"), "{name} {args:?}: {stderr}");
        }
        assert!(!out.exists(), "{name}: nothing written");
    }
}
