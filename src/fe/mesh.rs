//! Structured, geometrically graded hexahedral mesh of the quarter block
//! `[0, Lx] × [0, Ly] × [-D, 0]` (top surface `z = 0`, contact at the origin).
//!
//! Elements are tensor-product Lagrange hexahedra of order 1 (8 nodes) or 2
//! (27 nodes) (Zienkiewicz & Taylor, *The Finite Element Method*, vol. 1, §8.5).
//! The mesh is a tensor product of three 1-D graded edge lists: uniform elements
//! of size `h` over the fine zone, then sizes growing geometrically by a fixed ratio
//! up to the block size.

use crate::fe::FeError;

/// A structured hexahedral mesh with a node grid of `dims[0] × dims[1] × dims[2]`
/// nodes; node `(i, j, k)` has index `i + nx (j + ny k)`, `k = nz - 1` is the top.
#[derive(Debug, Clone)]
pub struct HexMesh {
    /// Element order: 1 (8-node) or 2 (27-node).
    pub order: usize,
    pub nodes: Vec<[f64; 3]>,
    /// Node-grid dimensions.
    pub dims: [usize; 3],
    /// Element-grid dimensions.
    pub elem_dims: [usize; 3],
    /// Element edge coordinates along x, y, z (ascending).
    pub edges: [Vec<f64>; 3],
}

/// 1-D graded edge coordinates from `0` to `total`: `n_fine` uniform elements of
/// size `h`, then elements growing geometrically by `growth`, the graded part rescaled
/// so that the last edge is exactly `total`.
pub fn graded_edges(h: f64, n_fine: usize, growth: f64, total: f64) -> Result<Vec<f64>, FeError> {
    if !(h > 0.0 && growth >= 1.0 && total > 0.0 && n_fine >= 1 && h.is_finite()) {
        return Err(FeError::InvalidInput(format!(
            "graded mesh: h={h}, n_fine={n_fine}, growth={growth}, total={total}"
        )));
    }
    let fine = h * n_fine as f64;
    let mut edges: Vec<f64> = (0..=n_fine).map(|i| h * i as f64).collect();
    if fine >= total {
        return Err(FeError::InvalidInput(format!("fine zone {fine} exceeds block size {total}")));
    }
    let mut sizes = Vec::new();
    let mut s = h;
    let mut sum = 0.0;
    while sum < total - fine {
        s *= growth;
        sizes.push(s);
        sum += s;
        if sizes.len() > 10_000 {
            return Err(FeError::InvalidInput("graded mesh too long".into()));
        }
    }
    // Drop the last element if that brings the total closer, then rescale.
    if sizes.len() > 1 && (sum - (total - fine)) > 0.5 * sizes[sizes.len() - 1] {
        sum -= sizes.pop().unwrap_or(0.0);
    }
    let scale = (total - fine) / sum;
    let mut x = fine;
    for s in sizes {
        x += s * scale;
        edges.push(x);
    }
    let last = edges.len() - 1;
    edges[last] = total;
    Ok(edges)
}

/// Node coordinates along one axis for the given element edges and order
/// (equally spaced nodes inside each element).
fn axis_nodes(edges: &[f64], order: usize) -> Vec<f64> {
    let mut v = Vec::with_capacity(order * (edges.len() - 1) + 1);
    for w in edges.windows(2) {
        for a in 0..order {
            v.push(w[0] + (w[1] - w[0]) * a as f64 / order as f64);
        }
    }
    v.push(edges[edges.len() - 1]);
    v
}

impl HexMesh {
    /// Tensor-product mesh from ascending edge coordinates along x, y and z.
    pub fn structured(order: usize, xe: &[f64], ye: &[f64], ze: &[f64]) -> Result<Self, FeError> {
        if !(order == 1 || order == 2) {
            return Err(FeError::InvalidInput(format!("element order {order}")));
        }
        for e in [xe, ye, ze] {
            if e.len() < 2 || e.windows(2).any(|w| w[1].is_nan() || w[1] <= w[0]) {
                return Err(FeError::InvalidInput("edges must ascend".into()));
            }
        }
        let [ax, ay, az] = [xe, ye, ze].map(|e| axis_nodes(e, order));
        let dims = [ax.len(), ay.len(), az.len()];
        let mut nodes = Vec::with_capacity(dims[0] * dims[1] * dims[2]);
        for &z in &az {
            for &y in &ay {
                for &x in &ax {
                    nodes.push([x, y, z]);
                }
            }
        }
        Ok(Self {
            order,
            nodes,
            dims,
            elem_dims: [xe.len() - 1, ye.len() - 1, ze.len() - 1],
            edges: [xe.to_vec(), ye.to_vec(), ze.to_vec()],
        })
    }

    /// Node index of grid position `(i, j, k)`.
    #[inline]
    pub fn node_index(&self, i: usize, j: usize, k: usize) -> usize {
        i + self.dims[0] * (j + self.dims[1] * k)
    }

    pub fn n_elements(&self) -> usize {
        self.elem_dims.iter().product()
    }

    /// Global node indices of element `e`, local node `(a, b, c)` at position
    /// `a + (p+1)(b + (p+1) c)`.
    pub fn element_nodes(&self, e: usize, out: &mut Vec<usize>) {
        let [ex, ey, _] = self.elem_dims;
        let (i, j, k) = (e % ex, (e / ex) % ey, e / (ex * ey));
        let p = self.order;
        out.clear();
        for c in 0..=p {
            for b in 0..=p {
                for a in 0..=p {
                    out.push(self.node_index(p * i + a, p * j + b, p * k + c));
                }
            }
        }
    }

    /// Moves the element vertices by `f` and places every other node by trilinear
    /// interpolation of its element's vertices (straight-edged distorted mesh; used
    /// by the patch test).
    pub fn map_vertices(&mut self, f: impl Fn([f64; 3]) -> [f64; 3]) {
        let p = self.order;
        let [nx, ny, nz] = self.dims;
        let old = self.nodes.clone();
        let vert = |i: usize, j: usize, k: usize| f(old[i + nx * (j + ny * k)]);
        for k in 0..nz {
            for j in 0..ny {
                for i in 0..nx {
                    let (ei, ej, ek) = (
                        (i / p).min(self.elem_dims[0] - 1),
                        (j / p).min(self.elem_dims[1] - 1),
                        (k / p).min(self.elem_dims[2] - 1),
                    );
                    let t = [
                        (i - p * ei) as f64 / p as f64,
                        (j - p * ej) as f64 / p as f64,
                        (k - p * ek) as f64 / p as f64,
                    ];
                    let mut x = [0.0; 3];
                    for (c, wc) in [(0, 1.0 - t[2]), (1, t[2])] {
                        for (b, wb) in [(0, 1.0 - t[1]), (1, t[1])] {
                            for (a, wa) in [(0, 1.0 - t[0]), (1, t[0])] {
                                let v = vert(p * (ei + a), p * (ej + b), p * (ek + c));
                                for d in 0..3 {
                                    x[d] += wa * wb * wc * v[d];
                                }
                            }
                        }
                    }
                    self.nodes[i + nx * (j + ny * k)] = x;
                }
            }
        }
    }

    /// Geometric nested-dissection ordering of the nodes (George 1973): the node
    /// box is split recursively by a plane of nodes lying on element faces (so the two
    /// halves share no element), the halves first and the separator plane last.
    /// Much less fill than minimum degree for 3-D meshes.
    pub fn nested_dissection(&self) -> Vec<usize> {
        let mut out = Vec::with_capacity(self.nodes.len());
        let full = [[0, self.dims[0]], [0, self.dims[1]], [0, self.dims[2]]];
        self.dissect(full, &mut out);
        out
    }

    fn dissect(&self, b: [[usize; 2]; 3], out: &mut Vec<usize>) {
        let p = self.order;
        let len = |d: usize| b[d][1] - b[d][0];
        let count = len(0) * len(1) * len(2);
        let mut dims = [0, 1, 2];
        dims.sort_by_key(|&d| std::cmp::Reverse(len(d)));
        // separator index: a multiple of the order strictly inside the range
        let split = dims.iter().find_map(|&d| {
            let (lo, hi) = (b[d][0], b[d][1]);
            let mid = (lo + hi) / 2;
            let s = (mid / p) * p;
            (count > 64 && s > lo && s + 1 < hi).then_some((d, s))
        });
        match split {
            None => {
                for k in b[2][0]..b[2][1] {
                    for j in b[1][0]..b[1][1] {
                        for i in b[0][0]..b[0][1] {
                            out.push(self.node_index(i, j, k));
                        }
                    }
                }
            }
            Some((d, s)) => {
                let mut left = b;
                left[d] = [b[d][0], s];
                let mut right = b;
                right[d] = [s + 1, b[d][1]];
                let mut sep = b;
                sep[d] = [s, s + 1];
                self.dissect(left, out);
                self.dissect(right, out);
                self.dissect(sep, out);
            }
        }
    }

    /// Tributary areas `∫ N_i dA` of the top-surface nodes (grid `(i, j)`,
    /// index `i + nx j`) for the rectangular top faces of the structured mesh.
    /// Positive for Lagrange elements (weights h/2, h/2 for order 1;
    /// h/6, 2h/3, h/6 for order 2: Simpson).
    pub fn top_tributary_areas(&self) -> Vec<f64> {
        let w1 = |edges: &[f64]| -> Vec<f64> {
            let n = self.order * (edges.len() - 1) + 1;
            let mut w = vec![0.0; n];
            for (e, s) in edges.windows(2).enumerate() {
                let h = s[1] - s[0];
                if self.order == 1 {
                    w[e] += h / 2.0;
                    w[e + 1] += h / 2.0;
                } else {
                    w[2 * e] += h / 6.0;
                    w[2 * e + 1] += 2.0 * h / 3.0;
                    w[2 * e + 2] += h / 6.0;
                }
            }
            w
        };
        let (wx, wy) = (w1(&self.edges[0]), w1(&self.edges[1]));
        wy.iter().flat_map(|y| wx.iter().map(move |x| x * y)).collect()
    }
}
