//! Circles in a directed graph: its strongly connected components of more than one node, each
//! shown by one circle through it.
use std::collections::{BTreeMap, BTreeSet, VecDeque};

/// A group of nodes that reach each other (a strongly connected component of two or more nodes).
#[derive(Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Circle {
    /// Its nodes, sorted.
    pub members: Vec<String>,
    /// A shortest circle through its first node, ending where it starts (`[a, b, a]`).
    pub path: Vec<String>,
}

/// Every circle of `graph`, sorted, so the answer does not depend on the order of the map.
pub fn circles(graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<Circle> {
    let mut out: Vec<Circle> = components(graph)
        .into_iter()
        .filter(|c| c.len() > 1)
        .map(|members| Circle {
            path: shortest_circle(graph, &members),
            members,
        })
        .collect();
    out.sort();
    out
}

/// The strongly connected components (Tarjan's algorithm, iterative), each sorted.
fn components(graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    let nodes: Vec<&String> = graph.keys().collect();
    let id: BTreeMap<&String, usize> = nodes.iter().enumerate().map(|(k, n)| (*n, k)).collect();
    let succ: Vec<Vec<usize>> = nodes
        .iter()
        .map(|n| {
            graph[*n]
                .iter()
                .filter_map(|m| id.get(m).copied())
                .collect()
        })
        .collect();
    let n = nodes.len();
    let (mut index, mut low, mut on_stack) = (vec![usize::MAX; n], vec![0; n], vec![false; n]);
    let (mut stack, mut out, mut next) = (Vec::new(), Vec::new(), 0);
    for start in 0..n {
        if index[start] != usize::MAX {
            continue;
        }
        // (node, next successor to look at)
        let mut work = vec![(start, 0usize)];
        while let Some(&mut (v, ref mut k)) = work.last_mut() {
            if *k == 0 && index[v] == usize::MAX {
                index[v] = next;
                low[v] = next;
                next += 1;
                stack.push(v);
                on_stack[v] = true;
            }
            if let Some(&w) = succ[v].get(*k) {
                *k += 1;
                if index[w] == usize::MAX {
                    work.push((w, 0));
                } else if on_stack[w] {
                    low[v] = low[v].min(index[w]);
                }
                continue;
            }
            work.pop();
            if let Some(&(u, _)) = work.last() {
                low[u] = low[u].min(low[v]);
            }
            if low[v] == index[v] {
                let mut c = Vec::new();
                while let Some(w) = stack.pop() {
                    on_stack[w] = false;
                    c.push(nodes[w].clone());
                    if w == v {
                        break;
                    }
                }
                c.sort();
                out.push(c);
            }
        }
    }
    out
}

/// A shortest circle through the first node of `component`, inside it (breadth first).
fn shortest_circle(
    graph: &BTreeMap<String, BTreeSet<String>>,
    component: &[String],
) -> Vec<String> {
    let inside: BTreeSet<&String> = component.iter().collect();
    let start = &component[0];
    let mut came_from: BTreeMap<&String, &String> = BTreeMap::new();
    let mut queue = VecDeque::from([start]);
    while let Some(v) = queue.pop_front() {
        for w in graph[v].iter().filter(|w| inside.contains(w)) {
            if w == start {
                let mut path = vec![start.clone()];
                let mut at = v;
                while at != start {
                    path.push(at.clone());
                    at = came_from[at];
                }
                path.push(start.clone());
                path.reverse();
                return path;
            }
            if !came_from.contains_key(w) {
                came_from.insert(w, v);
                queue.push_back(w);
            }
        }
    }
    unreachable!("a strongly connected component has a circle through each of its nodes")
}
