//! The files the stages' scene files name (the cow's mesh, material and texture),
//! compiled into the WebAssembly module, since a page has no files to read.

use std::sync::OnceLock;

use raycourse::{InMemory, scene_file::crate_folder};

/// Every file a stage names, relative to the crate's folder, and its bytes.
const FILES: [(&str, &[u8]); 3] = [
    (
        "assets/spot/spot.obj",
        include_bytes!("../../assets/spot/spot.obj"),
    ),
    (
        "assets/spot/spot.mtl",
        include_bytes!("../../assets/spot/spot.mtl"),
    ),
    (
        "assets/spot/spot_texture.png",
        include_bytes!("../../assets/spot/spot_texture.png"),
    ),
];

/// The stages' files, under the names a stage reads them by
/// ([`Stage::file`](raycourse::Stage::file)'s folder): gathered on the first call,
/// and shared by every scene of the page.
pub fn stage_files() -> &'static InMemory {
    static BY_NAME: OnceLock<InMemory> = OnceLock::new();
    BY_NAME.get_or_init(|| {
        let mut files = InMemory::default();
        for (path, bytes) in FILES {
            files.insert(crate_folder().join(path), bytes.to_vec());
        }
        files
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use raycourse::Overrides;

    #[test]
    fn every_stage_finds_its_files_in_memory() {
        let files = stage_files();
        for stage in raycourse::stages() {
            let scene = stage.scene_from(&Overrides::default(), files);
            assert!(scene.is_ok(), "{}: {:?}", stage.name, scene.err());
        }
    }

    #[test]
    fn the_textured_stage_gets_its_texture_from_memory() {
        let stage = raycourse::find_stage(7, "textures").unwrap();
        let scene = stage
            .scene_from(&Overrides::default(), stage_files())
            .unwrap();
        let textured = matches!(
            scene.meshes[0].albedo,
            raycourse::meshes::MeshAlbedo::Texture(_)
        );
        assert!(textured, "the cow is textured from the compiled-in PNG");
    }
}
