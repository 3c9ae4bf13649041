//! The items of `src/output/sink.rs`.

use pegdyn::error::OutputError;
use pegdyn::output::csv::format_f64;
use pegdyn::output::memory::Column;
use pegdyn::output::memory::Keep;
use pegdyn::output::names::Part;
use pegdyn::output::plot::Figure;
use pegdyn::output::plot::{Panel, Series};
use pegdyn::output::sink::*;
use std::path::{Path, PathBuf};

fn temp_dir(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pegdyn-sink-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn memory_keeps_typed_columns_and_touches_no_disk() {
    let sink = Sink::memory("t", Keep::Tables);
    let mut w = sink.table(Part::Main, &["x", "label", "y"]).unwrap();
    w.row_cells(&["0.5", "a", "1e-12"]).unwrap();
    w.row_cells(&[&format_f64(1.0 / 3.0), "b", "-inf"])
        .unwrap_err();
    w.row_cells(&[&format_f64(1.0 / 3.0), "b", "2"]).unwrap();
    w.finish().unwrap();
    assert!(!Path::new("t.csv").exists());
    assert!(sink.written().is_empty());
    let t = sink.into_tables();
    assert_eq!(t.len(), 1);
    assert_eq!((t[0].file.as_str(), t[0].stem()), ("t.csv", "t".into()));
    assert_eq!(t[0].header, ["x", "label", "y"]);
    assert_eq!(t[0].columns[0], Column::Numbers(vec![0.5, 1.0 / 3.0]));
    assert_eq!(t[0].columns[1], Column::Text(vec!["a".into(), "b".into()]));
    assert_eq!(t[0].columns[2], Column::Numbers(vec![1e-12, 2.0]));
}

#[test]
fn non_finite_values_are_refused_in_memory_as_for_a_file() {
    let dir = temp_dir("nan");
    for sink in [Sink::memory("n", Keep::Nothing), Sink::directory(&dir, "n")] {
        let mut w = sink.table(Part::Sub("x"), &["t_s", "x_m"]).unwrap();
        w.row(&[0.0, 1.0]).unwrap();
        let e = w.row(&[0.1, f64::NAN]).unwrap_err().to_string();
        assert!(
            e.contains("n.x.csv") && e.contains("x_m") && e.contains("NaN"),
            "{e}"
        );
        assert_eq!(w.rows(), 1);
        drop(w);
        assert!(sink.written().is_empty() && sink.into_tables().is_empty());
    }
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_directory_records_what_it_wrote_and_refuses_protected_paths() {
    let dir = temp_dir("dir");
    let scene = dir.join("s.svg");
    std::fs::write(&scene, "kind = 1").unwrap();
    let sink = Sink::directory(&dir, "s").protecting(&scene);
    let mut w = sink.table(Part::Main, &["t_s"]).unwrap();
    w.row(&[1.0]).unwrap();
    w.finish().unwrap();
    sink.file(Part::Sub("note"), "txt", b"hello").unwrap();
    let fig = Figure {
        panels: vec![Panel::new("p", "x", "y").with(Series::line("a", vec![(0.0, 1.0)]))],
        ..Figure::new()
    };
    let e = sink.figure(Part::Main, &fig).unwrap_err();
    assert!(matches!(e, OutputError::WouldOverwriteScene { .. }), "{e}");
    assert_eq!(std::fs::read_to_string(&scene).unwrap(), "kind = 1");
    sink.figure(Part::Sub("fig"), &fig).unwrap();
    assert_eq!(
        sink.written(),
        [
            dir.join("s.csv"),
            dir.join("s.note.txt"),
            dir.join("s.fig.svg")
        ]
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("s.csv")).unwrap(),
        "t_s\n1\n"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn memory_keeps_other_files_whole_only_when_keeping_tables() {
    let kept = Sink::memory("k", Keep::Tables);
    assert!(kept.keeps_files());
    kept.file(Part::Main, "html", b"<p>1</p>").unwrap();
    kept.file(Part::Sub("x"), "txt", b"two").unwrap();
    assert!(!Path::new("k.html").exists() && kept.written().is_empty());
    let files = kept.take_files();
    let names: Vec<&str> = files.iter().map(|f| f.file.as_str()).collect();
    assert_eq!(names, ["k.html", "k.x.txt"]);
    assert_eq!(files[0].bytes, b"<p>1</p>");
    assert!(kept.take_files().is_empty());
    let dropped = Sink::memory("d", Keep::Nothing);
    assert!(!dropped.keeps_files());
    dropped.file(Part::Main, "html", b"<p>1</p>").unwrap();
    assert!(dropped.take_files().is_empty());
}

#[test]
fn an_empty_figure_is_refused_in_memory_without_drawing() {
    let sink = Sink::memory("e", Keep::Tables);
    let fig = Figure {
        panels: vec![Panel::new("nothing", "x", "y").with(Series::line("a", vec![]))],
        ..Figure::new()
    };
    let e = sink.figure(Part::Main, &fig).unwrap_err();
    assert!(matches!(e, OutputError::EmptyPlot { .. }), "{e}");
    assert_eq!(sink.path(Part::Main, "svg"), Path::new("e.svg"));
}
