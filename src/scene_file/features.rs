//! Which course session this build was compiled for.
//!
//! The Cargo features `s1`..`s7` decide what code exists; a scene file decides what a
//! render uses. When a scene asks for something this build lacks, the loader names
//! the feature that brings it, using the session number below.

use crate::messages::said::Said;

/// The last course session enabled in this build: 7 with feature `s7` (the default),
/// 1 with `s1` alone. The build script (`build.rs`) finds it.
pub const SESSION: u32 = (env!("RAYCOURSE_SESSION").as_bytes()[0] - b'0') as u32;

/// What this crate is, which decides how a later session is named to its reader.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Made {
    /// The course's crate, whose sessions are Cargo features.
    Features,
    /// A session view (`cargo xtask view sN`): the crate after one session.
    View,
    /// A student's exercise crate (`cargo xtask exercise sN`).
    Exercises,
}

/// What this build is, as the build script (`build.rs`) found it.
pub const MADE: Made = match env!("RAYCOURSE_MADE").as_bytes()[0] {
    b'v' => Made::View,
    b'e' => Made::Exercises,
    _ => Made::Features,
};

/// What a scene that asks for a part of session `later` is told in this build,
/// after what it asked for: "needs feature s4: ..." in the course's crate.
pub fn comes_with(later: u32) -> Said {
    remedy(MADE, later, SESSION)
}

/// What a scene that asks for a part of session `later` is told in a crate `made`
/// so that stops at `session`: the feature to enable, or the session that brings it.
pub fn remedy(made: Made, later: u32, session: u32) -> Said {
    let id = match made {
        Made::Features => "scene-needs-feature-s",
        Made::View => "scene-comes-with-view",
        Made::Exercises => "scene-comes-with-exercises",
    };
    Said::new(id)
        .with("later", u64::from(later))
        .with("session", u64::from(session))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_kind_of_crate_names_the_later_session_its_way() {
        assert_eq!(
            remedy(Made::Features, 4, 3).to_string(),
            "needs feature s4: cargo run --features s4 -- ..."
        );
        assert_eq!(
            remedy(Made::View, 4, 3).to_string(),
            "comes with session 4: this crate stops at session 3 (`cargo xtask view s4 DIR` in the course's crate writes session 4's)"
        );
        assert_eq!(
            remedy(Made::Exercises, 4, 3).to_string(),
            "comes with session 4: you write it then; this crate holds session 3's exercises"
        );
    }
}
