//! The items of `src/compliant_peg_3d/search/trig.rs`.

use pegdyn::compliant_peg_3d::search::trig::Trig2;

fn f(t: &Trig2, th: f64) -> [f64; 3] {
    t.at(th.cos(), th.sin())
}

#[test]
fn derivatives_match_central_differences() {
    let t = Trig2 {
        a0: 0.3,
        a1: -1.2,
        b1: 0.4,
        a2: 0.7,
        b2: -0.9,
    };
    let h = 1e-5;
    for k in 0..20 {
        let th = 0.31 * k as f64;
        let [_, d1, d2] = f(&t, th);
        let fd1 = (f(&t, th + h)[0] - f(&t, th - h)[0]) / (2.0 * h);
        let fd2 = (f(&t, th + h)[1] - f(&t, th - h)[1]) / (2.0 * h);
        assert!((d1 - fd1).abs() < 1e-8 && (d2 - fd2).abs() < 1e-8, "{th}");
    }
}

#[test]
fn enclosures_contain_dense_samples() {
    let t = Trig2 {
        a0: 1.0,
        a1: 0.5,
        b1: -2.0,
        a2: 1.5,
        b2: 0.25,
    };
    for (m, w) in [(0.0, 0.8), (1.0, 0.1), (2.5, 1.6), (-0.7, 0.01)] {
        let e = t.bounded().enclose(f64::cos(m), f64::sin(m), w);
        for k in 0..=1000 {
            let th = m - w + 2.0 * w * k as f64 / 1000.0;
            let [v, d1, d2] = f(&t, th);
            assert!(e.value.lo <= v && v <= e.value.hi, "value at {th}");
            assert!(e.d1.lo <= d1 && d1 <= e.d1.hi, "d1 at {th}");
            assert!(e.d2.lo <= d2 && d2 <= e.d2.hi, "d2 at {th}");
        }
    }
}
