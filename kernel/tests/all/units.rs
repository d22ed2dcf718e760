//! Unit tests of the kernel's interval arithmetic (`orbit::interval`), the square roots of the
//! basin drops (`basin::drop`) and the bisection tree (`basin::tree`): they lived inside src/, which
//! made the kernel library a test harness of its own, compiled a second time at full optimisation
//! (CI, issue 23 §4; `[lib] test = false`, tests/all/toolchain.rs).
#![cfg(feature = "basin")]

mod interval {
    use chatter_kernel::exact::{Field, Int, OrderedField};
    use chatter_kernel::orbit::interval::*;
    use malachite::rational::Rational as Q;
    use num_rational::BigRational;

    fn rounding_brackets<F: Field>() {
        for (n, d) in [(1, 3), (-1, 3), (22, 7), (-355, 113), (1, 1 << 40), (7, 1), (0, 1)] {
            let x = F::from_ratio(n, d);
            let (lo, hi) = (round_down(&x), round_up(&x));
            assert!(lo <= x && x <= hi, "{n}/{d}");
            // Short: the denominators are powers of two of at most PRECISION + 2 + |exponent| bits.
            assert!(lo.denom().bit_length() <= PRECISION + 48 && hi.denom().bit_length() <= PRECISION + 48);
            // Tight: relative width below 2^-60.
            let width = hi.minus(&lo);
            let bound = F::from_ratio(1, 1 << 60).times(&x.plus(&x).max(x.negated().plus(&x.negated())));
            assert!(width <= bound, "{n}/{d}");
        }
    }

    #[test]
    fn outward_rounding_brackets_the_number_on_both_backends() {
        rounding_brackets::<Q>();
        rounding_brackets::<BigRational>();
    }

    #[test]
    fn interval_and_dual_operations_enclose_their_values() {
        let iv = |a: i64, b: i64| Iv::<Q> { lo: Q::from_ratio(a, 10), hi: Q::from_ratio(b, 10) };
        let (x, y) = (iv(-3, 2), iv(5, 7));
        let p = x.times(&y);
        assert!(p.lo <= Q::from_ratio(-21, 100) && p.hi >= Q::from_ratio(14, 100));
        let q = x.over(&y).unwrap();
        assert!(q.lo <= Q::from_ratio(-3, 5) && q.hi >= Q::from_ratio(2, 7));
        assert!(y.over(&x).is_none(), "a divisor containing 0");
        // d/dy (y^2 / (y + 1)) at y in [1, 2]: (y^2 + 2y)/(y + 1)^2 lies in [3/4, 8/9].
        let one = Iv::point(&Q::from_ratio(1, 1));
        let zero = Iv::zero();
        let y =
            Dual { v: Iv { lo: Q::from_ratio(1, 1), hi: Q::from_ratio(2, 1) }, d: [one, zero.clone(), zero] };
        let f = y.times(&y).over(&y.plus(&Dual::constant(&Q::from_ratio(1, 1)))).unwrap();
        assert!(f.d[0].lo <= Q::from_ratio(3, 4) && f.d[0].hi >= Q::from_ratio(8, 9));
        assert!(f.v.lo <= Q::from_ratio(1, 2) && f.v.hi >= Q::from_ratio(4, 3));
    }
}

mod drop {
    use chatter_kernel::basin::drop::*;
    use chatter_kernel::exact::Field;
    use chatter_kernel::orbit::interval::Iv;
    use malachite::rational::Rational as Q;
    use num_rational::BigRational;

    fn roots<F: Field>() {
        for (n, d) in [(3, 4), (2, 1), (1, 1), (0, 1), (1, 3), (10_000, 7)] {
            let x = F::from_ratio(n, d);
            let e = sqrt_enclosure(&Iv::exact(&x));
            assert!(e.lo.times(&e.lo) <= x && x <= e.hi.times(&e.hi), "{n}/{d}");
            // Tight: 64-bit mantissas, so a width below 2^-50 for roots below 64.
            assert!(e.hi.minus(&e.lo) <= F::from_ratio(1, 1 << 50), "{n}/{d}");
        }
    }

    #[test]
    fn square_roots_are_enclosed_tightly_on_both_backends() {
        roots::<Q>();
        roots::<BigRational>();
    }
}

mod tree {
    use chatter_kernel::basin::tree::*;

    #[test]
    fn a_bisection_tree_is_a_partition_and_gaps_overlaps_and_mixed_axes_are_not() {
        assert_eq!(partition([""], 5), Ok(()));
        assert_eq!(partition(["0", "1"], 5), Ok(()));
        assert_eq!(partition(["02", "03", "1"], 5), Ok(()));
        assert_eq!(partition(["0", "2"], 5), Err(TreeError::Axis(1)));
        assert_eq!(partition(["0"], 5), Err(TreeError::Uncovered));
        assert_eq!(partition(["0", "1", "0"], 5), Err(TreeError::Overlap(2)));
        assert_eq!(partition(["0", "01"], 5), Err(TreeError::Overlap(1)));
        assert_eq!(partition(["01", "0"], 5), Err(TreeError::Overlap(1)));
        assert_eq!(partition(["a"], 5), Err(TreeError::Digit(0, 0)));
        assert_eq!(partition(["9", "8"], 5), Ok(()));
        assert_eq!(partition(["9", "8"], 4), Err(TreeError::Digit(0, 0)));
    }
}
