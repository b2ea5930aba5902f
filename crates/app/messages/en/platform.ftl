# What differs between the window and the page (src/gui/platform/native.rs and web.rs).

drop-hint-window = or drop a mesh, a body .toml or a robot .urdf/.sdf/.xml on the window
drop-hint-page = or drop a mesh, or a body .toml with its meshes, on the page
no-file-chosen-window = no file chosen (if no dialog appeared, this desktop has no file-dialog portal: type a path or drop the file on the window)
no-file-chosen-page = no file chosen
record-hint-window = the window as numbered PNG pictures, 10 per second
record-hint-page = the page as numbered PNG pictures, 10 per second, in one .zip download
share-hint-window = put it after the address of the lab's page
share-hint-page = it opens this scene in the page
dialog-body-files = Body files
dialog-gltf-binary = glTF binary
