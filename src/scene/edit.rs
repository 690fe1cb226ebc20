//! Editing a frozen scene: thawed back into a scene under construction with everything it
//! holds, the text its file held beyond the records too, whose records the builder then
//! replaces or takes out in place, the names and kept text of the others following them.

use super::kept::{Kept, KeptAt, Object};
use super::{PoolStr, Scene, SceneBuilder, Str, UserDataText};

/// The index a record at `index` has once the record at `removed` is taken out; None for
/// that record itself.
fn index_without(index: u32, removed: u32) -> Option<u32> {
    match index.cmp(&removed) {
        std::cmp::Ordering::Less => Some(index),
        std::cmp::Ordering::Equal => None,
        std::cmp::Ordering::Greater => Some(index - 1),
    }
}

impl Object {
    /// The same object once `removed` is taken out; None for `removed` itself.
    fn without(self, removed: Object) -> Option<Object> {
        match (self, removed) {
            (Object::Shape(i), Object::Shape(r)) => index_without(i, r).map(Object::Shape),
            (Object::Fixture(i), Object::Fixture(r)) => index_without(i, r).map(Object::Fixture),
            (Object::Body(i), Object::Body(r)) => index_without(i, r).map(Object::Body),
            (Object::Joint(i), Object::Joint(r)) => index_without(i, r).map(Object::Joint),
            _ => Some(self),
        }
    }
}

impl SceneBuilder {
    /// A scene under construction holding everything `scene` holds but its diagnostics,
    /// which describe the file it was read from.
    pub fn thaw(scene: &Scene) -> SceneBuilder {
        let mut b = SceneBuilder::default();
        (b.version, b.dialect, b.gravity) = (scene.version, Some(scene.dialect), scene.gravity);
        b.world_axes.clone_from(&scene.beyond.world_axes);
        b.vertices.clone_from(&scene.vertices);
        b.fixture_ids.clone_from(&scene.fixture_ids);
        for s in &scene.shapes {
            let name = b.thawed(scene, s.name);
            b.push_shape(super::Shape { name: Str::NULL, ..*s }, name);
        }
        for f in &scene.fixtures {
            let name = b.thawed(scene, f.name);
            b.push_fixture(super::Fixture { name: Str::NULL, ..*f }, name);
        }
        for body in &scene.bodies {
            let name = b.thawed(scene, body.name);
            b.push_body(super::Body { name: Str::NULL, ..*body }, name);
        }
        for j in &scene.joints {
            let name = b.thawed(scene, j.name);
            b.push_joint(super::Joint { name: Str::NULL, ..*j }, name);
        }
        for u in &scene.user_data {
            let raw = b.add_str(scene.text(u.raw).unwrap_or_default());
            let (type_name, value) = (b.thawed(scene, u.type_name), b.thawed(scene, u.value));
            b.user_data.push(UserDataText { raw, type_name, value });
        }
        for piece in &scene.beyond.pieces {
            let text = b.keep_str(scene.beyond.text(piece));
            b.kept.push(Kept { object: piece.object, place: piece.place, text });
        }
        b
    }

    fn thawed(&mut self, scene: &Scene, s: Str) -> Option<PoolStr> {
        scene.text(s).map(|text| self.add_str(text))
    }

    fn names_of(&mut self, object: Object) -> Option<(&mut Vec<(u32, PoolStr)>, u32)> {
        match object {
            Object::World => None,
            Object::Shape(i) => Some((&mut self.names.shapes, i)),
            Object::Fixture(i) => Some((&mut self.names.fixtures, i)),
            Object::Body(i) => Some((&mut self.names.bodies, i)),
            Object::Joint(i) => Some((&mut self.names.joints, i)),
        }
    }

    /// Gives `object`, whose record was replaced, `name`, and forgets the text its file
    /// held inside it (unknown attributes and elements, a Farseer-only joint's whole
    /// text), which belonged to the record replaced; the comments around it stay.
    pub fn replaced(&mut self, object: Object, name: Option<PoolStr>) {
        if let Some((names, index)) = self.names_of(object) {
            names.retain(|&(i, _)| i != index);
            names.extend(name.map(|name| (index, name)));
        }
        self.kept
            .retain(|k| k.object != object || matches!(k.place, KeptAt::Before | KeptAt::After));
    }

    /// Forgets `object`, whose record was taken out: its name and the text its file held
    /// in and around it go, and the names and kept text of the objects of its kind after
    /// it move down one.
    pub fn taken_out(&mut self, object: Object) {
        if let Some((names, index)) = self.names_of(object) {
            let moved = |&(i, name): &(u32, PoolStr)| index_without(i, index).map(|i| (i, name));
            *names = names.iter().filter_map(moved).collect();
        }
        let moved = |k: &Kept<_>| k.object.without(object).map(|object| Kept { object, ..*k });
        self.kept = self.kept.iter().filter_map(moved).collect();
        if let Object::Joint(index) = object {
            let moved = |&(j, axis): &(u32, _)| index_without(j, index).map(|j| (j, axis));
            self.world_axes = self.world_axes.iter().filter_map(moved).collect();
        }
    }
}
