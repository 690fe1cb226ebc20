use super::Names;
use crate::markup::Name;

/// The table finds each known name, in any case, and nothing else: checked on lists
/// of every size up to the most an object has, against every other list's names.
#[test]
fn find_gives_the_index_of_the_name_in_any_case_and_nothing_else() {
    let pool: Vec<String> = (0..Names::MOST)
        .map(|i| match i % 4 {
            0 => format!("Element{i}"),
            1 => format!("LocalAnchorA{i}"),
            2 => format!("X{}", i * 7919),
            _ => format!("MaxMotorTorque{i}"),
        })
        .collect();
    let pool: &'static [&'static str] = Vec::leak(pool.into_iter().map(|n| &*n.leak()).collect());
    let others = ["Vertex", "vertex1", "ID", "", "CollideConnectedX", "名前"];
    for size in 1..=Names::MOST {
        let names = Names::new(&pool[..size]);
        for (i, name) in pool.iter().enumerate() {
            let expected = (i < size).then_some(i);
            for spelling in [name.to_string(), name.to_ascii_uppercase(), name.to_lowercase()] {
                assert_eq!(names.find(Name::new(&spelling).key()), expected, "{spelling}");
            }
            let near = format!("{name}x");
            assert_eq!(names.find(Name::new(&near).key()), None, "{near}");
        }
        for other in others {
            assert_eq!(names.find(Name::new(other).key()), None, "{other}");
        }
    }
}

#[test]
fn the_edit_distance_counts_a_swap_of_neighbours_as_one_edit() {
    let d = |a: &str, b: &str| super::edit_distance(a.as_bytes(), b.as_bytes());
    assert_eq!(d("", ""), 0);
    assert_eq!(d("", "Type"), 4);
    assert_eq!(d("Tpye", "Type"), 1);
    assert_eq!(d("DENSTY", "Density"), 1);
    assert_eq!(d("ab", "ba"), 1);
    assert_eq!(d("abc", "ca"), 3);
    assert_eq!(d("Radius", "Position"), 7);
    let long = "x".repeat(32);
    assert_eq!(d(&long, "Position"), 32);
    assert_eq!(super::nearest(&long, &["Position"]), None);
    assert_eq!(super::nearest("Poisiton", &["Position", "Positions"]), Some("Position"));
}
