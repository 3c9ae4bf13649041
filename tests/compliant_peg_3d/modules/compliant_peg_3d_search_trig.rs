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

#[test]
fn a_points_enclosure_is_the_arcs_at_zero_width() {
    // `enclose_point` leaves out the arc's terms; at `w = 0` they are
    // zero, so every bound equals `enclose`'s, bit for bit (signed zeros
    // included: a zero value at the angle).
    let mut seed = 0x5EED_2026_u64;
    let mut next = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let polys = [
        Trig2::default(),
        Trig2 {
            a0: 0.0,
            a1: 1.0,
            b1: 0.0,
            a2: 0.0,
            b2: 0.0,
        },
    ];
    let random: Vec<Trig2> = (0..200)
        .map(|_| Trig2 {
            a0: next() * 1e-3,
            a1: next() * 1e-4,
            b1: next() * 1e-4,
            a2: next() * 1e-5,
            b2: next() * 1e-5,
        })
        .collect();
    for t in polys.into_iter().chain(random) {
        let b = t.bounded();
        for k in 0..64 {
            let th = std::f64::consts::TAU * k as f64 / 64.0 + 0.1 * next();
            let (s, c) = th.sin_cos();
            let (p, a) = (b.enclose_point(c, s), b.enclose(c, s, 0.0));
            let bits = |v: f64| v.to_bits();
            for (x, y) in [
                (p.value.lo, a.value.lo),
                (p.value.hi, a.value.hi),
                (p.d1.lo, a.d1.lo),
                (p.d1.hi, a.d1.hi),
                (p.d2.lo, a.d2.lo),
                (p.d2.hi, a.d2.hi),
            ] {
                assert_eq!(bits(x), bits(y), "{t:?} at {th}: {x:e} against {y:e}");
            }
            assert_eq!(p.refinable, a.refinable);
        }
    }
}
