"""thespis.ar on real photos and synthetic footage: boards and camera files, frames as NumPy BGR
images, the ChArUco tutorial photos tracked as a picture sequence, OpenCV's gold marker corners,
a synthetic video written with VideoWriter and tracked against its truth, chessboard calibration,
the tracking session, the live capture, the live probe on a real mirror-ball photo, and the errors
a user meets."""

import json

import numpy as np
import pytest

import thespis
from thespis import ar
from conftest import SHARED_DATA

CHARUCO = "charuco:DICT_6X6_250:5x7:0.04:0.02"
GRID = "aruco-grid:DICT_4X4_50:4x3:0.04:0.01"


def vision(relative: str):
    path = SHARED_DATA / "vision" / relative
    if not path.exists():
        pytest.fail(f"missing real test data {path} (expected ../shared/data beside the repository)")
    return path


def charuco_photos():
    return [vision(f"aruco_real/charuco_img_0{i}.jpg") for i in range(4)]


def small_scene(frames, **options):
    camera = ar.CameraIntrinsics(320, 240, fx=300.0)
    return ar.SyntheticSource(GRID, camera, frames=frames, **options)


def test_boards_round_trip_through_their_text_and_bad_text_says_what_is_wrong():
    board = ar.parse_board(CHARUCO)
    assert board.kind == ar.BoardKind.charuco and board.dictionary == "DICT_6X6_250"
    assert (board.columns, board.rows) == (5, 7) and board.square == pytest.approx(0.04)
    assert board.second == pytest.approx(0.02) and not board.inverted
    assert board.marker_count == 17
    assert ar.parse_board(ar.format_board(board)) == board == ar.Board(str(board))
    chess = ar.Board("chessboard:9x6:0.025")
    corners = chess.chessboard_corners()
    assert corners.shape == (54, 3) and corners[1, 0] == pytest.approx(0.025) and np.all(corners[:, 2] == 0)
    with pytest.raises(ValueError, match="charuco:DICT_NOPE:5x7") as raised:
        ar.parse_board("charuco:DICT_NOPE:5x7:0.04:0.02")
    assert raised.value.code == thespis.ErrorCode.invalid_argument
    with pytest.raises(ValueError, match="aruco-grid:4x3"):
        ar.track(pictures=charuco_photos(), camera=vision("aruco_real/tutorial_camera_charuco.yml"), board="aruco-grid:4x3")


def test_camera_files_read_write_and_name_what_is_missing(tmp_path):
    camera = ar.read_camera_file(vision("aruco_real/tutorial_camera_charuco.yml"))
    assert (camera.width, camera.height) == (640, 480)
    assert camera.matrix.shape == (3, 3) and camera.matrix[0, 0] == camera.fx == pytest.approx(452.51072219637672)
    assert camera.distortion.shape == (5,) and camera.reprojection_error == pytest.approx(0.18234905535936044)
    ar.write_camera_file(tmp_path / "camera.yml", camera)
    assert ar.read_camera_file(tmp_path / "camera.yml") == camera
    assert ar.parse_camera_file(ar.format_camera_file(camera)) == camera
    made = ar.CameraIntrinsics(640, 480, fx=500.0, distortion=[0.1, 0, 0, 0])
    assert (made.fy, made.cx, made.cy) == (500.0, 320.0, 240.0)
    made.matrix = np.eye(3) * 2
    assert made.fx == 2.0 and made.cx == 0.0
    with pytest.raises(FileNotFoundError, match="no_such_camera.yml"):
        ar.read_camera_file(tmp_path / "no_such_camera.yml")
    with pytest.raises(FileNotFoundError, match="charuco_img_09.jpg"):
        ar.track(pictures=[vision("aruco_real/charuco_img_00.jpg"), tmp_path / "charuco_img_09.jpg"],
                 camera=camera, board=CHARUCO)


def test_frames_are_numpy_bgr_images_copied_in_and_viewed_out():
    frame = ar.read_picture(vision("aruco_real/charuco_img_00.jpg"))
    assert (frame.width, frame.height, frame.index, frame.time) == (640, 480, 0, 0.0)
    image = frame.image
    assert image.shape == (480, 640, 3) and image.dtype == np.uint8
    assert np.shares_memory(np.asarray(frame), frame.image)
    made = ar.VideoFrame(image, index=7, time=0.25)
    image[0, 0] = made.image[0, 0] ^ 0xFF  # writes through the view into `frame`, not into the copy
    np.testing.assert_array_equal(frame.image[0, 0], made.image[0, 0] ^ 0xFF)
    assert (made.index, made.time) == (7, 0.25)
    np.testing.assert_array_equal(ar.VideoFrame(image[:, ::-1]).image, image[:, ::-1])  # any strides
    with pytest.raises(ValueError, match=r"\(480, 640\) of float64"):
        ar.VideoFrame(np.zeros((480, 640)))
    with pytest.raises(ValueError, match="uint8"):
        ar.VideoFrame(np.zeros((4, 4, 3), np.float32))
    with pytest.raises(TypeError):
        ar.detect_markers("not a frame", "DICT_6X6_250")


def test_the_real_charuco_photos_track_as_pictures(tmp_path):
    reports = []
    result = ar.track(pictures=charuco_photos(), fps=1, camera=vision("aruco_real/tutorial_camera_charuco.yml"),
                      board=CHARUCO, out=tmp_path / "poses.csv", progress=lambda done, total: reports.append((done, total)))
    assert len(result) == 4 and result.statistics.frames == 4 and result.statistics.tracked == 4
    assert reports and reports[-1] == (4, 4)
    for i, frame in enumerate(result):
        assert frame.frame == i and frame.time == pytest.approx(i)
        assert frame.tracked and frame.has_pose
        assert frame.measured.features == 24  # every inner corner of the 5 × 7 board
        assert 0.33 < frame.tvec[2] < 0.43  # the tutorial's photos were taken 35–41 cm from the board
        assert frame.measured.information.shape == (6, 6)
        # Photos held still: no smear on the markers' edges, and the tilt not in doubt.
        assert 0 <= frame.measured.blur[0] < 2 and frame.measured.ambiguity > 3
    assert [f.event for f in result] == ["found", "", "", ""]
    rows = result.to_numpy()
    assert rows.shape == (4,) and rows["tracked"].all() and rows["rvec"].shape == (4, 3)
    np.testing.assert_allclose(rows["tvec"][2], result[2].tvec)
    assert list(rows["event"]) == ["found", "", "", ""]
    assert (tmp_path / "poses.csv").read_text() == result.csv()
    assert result.csv().startswith("frame,tracked,rx,ry,rz,tx,ty,tz,blur_px,blur_deg,ambiguity\n")


def test_a_tracking_session_gives_what_the_track_job_gives():
    camera = ar.read_camera_file(vision("aruco_real/tutorial_camera_charuco.yml"))
    job = ar.track(pictures=charuco_photos(), fps=1, camera=camera, board=ar.Board(CHARUCO), filter=False)
    tracker = ar.make_tracker(camera, board=CHARUCO)
    session = ar.TrackingSession(tracker, filter=False)
    assert session.tracker is tracker and "5" in tracker.description
    for i, path in enumerate(charuco_photos()):
        frame = session.process(ar.read_picture(path).image, time=float(i))
        assert frame.frame == i and frame.tracked and frame.measured.features == 24
        np.testing.assert_allclose(frame.tvec, job[i].tvec, atol=1e-9)
        np.testing.assert_allclose(frame.rvec, job[i].rvec, atol=1e-9)
        assert ar.translation_difference(frame.pose, job[i].pose) < 1e-9
    ids, pixels = tracker.charuco_corners
    assert len(ids) == 24 and pixels.shape == (24, 2)
    assert len(tracker.markers) >= 12 and tracker.corners is None
    assert session.tracking and session.statistics.frames == 4 and session.statistics.tracked == 4
    with pytest.raises(ValueError, match="needs its time"):
        session.process(ar.read_picture(charuco_photos()[0]).image)
    estimate = tracker.estimate(ar.read_picture(charuco_photos()[1]))
    assert estimate.found and estimate.features == 24 and estimate.reprojection_error < 1.0
    with pytest.raises(ValueError, match="chessboard"):
        ar.make_tracker(camera, board="chessboard:9x6:0.025")


def test_detected_markers_match_opencvs_gold_corners():
    gold = json.loads(vision("aruco_real/gold_detections.json").read_text())
    checked = 0
    for image in gold["images"]:
        if not image["dictionary"].startswith("DICT_") or "markers" not in image:
            continue  # a custom dictionary
        frame = ar.read_picture(vision("aruco_real") / image["file"])
        found = dict(ar.detect_markers(frame, image["dictionary"], whole_pixels=True))
        refined = ar.detect_markers(frame.image, image["dictionary"])
        assert len(refined) == len(found)
        for expected in image["markers"]:
            assert expected["id"] in found, (image["file"], expected["id"])
            corners = found[expected["id"]]
            assert corners.shape == (4, 2)
            np.testing.assert_allclose(corners, expected["corners_xy"], atol=1.0, err_msg=image["file"])
            checked += 1
    assert checked >= 20
    with pytest.raises(ValueError, match="DICT_NOPE"):
        ar.detect_markers(frame, "DICT_NOPE")


def test_a_synthetic_video_tracks_to_its_truth(tmp_path):
    camera = ar.read_camera_file(vision("calibration/left_intrinsics.yml"))
    camera.distortion = []
    source = ar.SyntheticSource(GRID, camera, frames=90, hidden=(40, 55))
    assert (source.width, source.height, source.frame_count, source.fps) == (640, 480, 90, 30.0)
    video = tmp_path / "board.mp4"
    with ar.VideoWriter(video, source.width, source.height, source.fps) as writer:
        for frame in source:
            writer.write(frame)
    assert writer.frames == 90 and video.exists()

    result = ar.track(video, camera=camera, board=source.board)
    assert len(result) == 90
    errors = []
    for frame in result:
        assert frame.tracked == source.visible(frame.frame), frame.frame
        if frame.tracked:
            errors.append(ar.translation_difference(frame.pose, source.truth(frame.frame)))
    assert len(errors) == 75
    assert np.mean(errors) < 0.002  # through H.264, as a camera's compression would be
    assert result.statistics.lost == 1
    assert [f.event for f in result if f.event] == ["found", "lost", "recovered"]


def test_calibration_finds_opencvs_intrinsics(tmp_path):
    views = sorted(vision("calibration").glob("left*.jpg"))
    gold = ar.read_camera_file(vision("calibration/left_intrinsics.yml"))
    reports = []
    calibration = ar.calibrate(views, "chessboard:9x6:0.025", fix_aspect=True, out=tmp_path / "left.yml",
                               progress=lambda done, total: reports.append((done, total)))
    assert reports
    camera = calibration.camera
    assert camera.fx == pytest.approx(gold.fx, rel=0.005)
    assert camera.fy == camera.fx  # fix_aspect
    assert (camera.width, camera.height) == (640, 480)
    assert len(calibration.views) == len(views) and all(v.found and v.corners == 54 for v in calibration.views)
    assert calibration.errors.shape == (len(views),) and np.all(calibration.errors < 2.0)
    assert calibration.rms == pytest.approx(camera.reprojection_error)
    assert np.all(calibration.deviations > 0)
    assert ar.read_camera_file(tmp_path / "left.yml") == camera

    def stop(done, total):
        raise RuntimeError("stopped by the callback")

    with pytest.raises(RuntimeError, match="stopped by the callback"):
        ar.calibrate(views, "chessboard:9x6:0.025", out=tmp_path / "never.yml", progress=stop)
    assert not (tmp_path / "never.yml").exists()


def test_there_is_no_camera_here_and_opening_one_says_so():
    assert ar.list_cameras() == []
    with pytest.raises(KeyError, match="No camera found at /dev/video63"):
        ar.open_camera(63)


def test_live_capture_delivers_frames_in_order_until_the_source_ends():
    source = small_scene(40)
    with ar.LiveCapture(source, real_time=False) as capture:
        indices = [frame.index for frame in capture]
        assert capture.state == "ended"
        assert "ended after 40 frames" in capture.message
        assert capture.captured == 40 and len(indices) + capture.dropped == 40
        assert indices == sorted(set(indices)) and indices[-1] == 39
        assert capture.newest(0) is None and capture.newest(0.05) is None
    assert source.truth(10) == source.truth(10)  # the source outlives the capture's use of it
    paced = ar.LiveCapture(small_scene(1000, fps=50), real_time=True)
    first = paced.newest(5.0)
    assert first is not None and first.image.shape == (240, 320, 3)
    paced.stop()
    assert paced.state == "stopped"


def test_video_files_and_sources_report_their_errors(tmp_path):
    with pytest.raises(ValueError, match="mp4 or .avi"):
        ar.VideoWriter(tmp_path / "out.mkv", 320, 240, 30)
    frame = next(iter(small_scene(2)))
    with pytest.raises(RuntimeError):
        with ar.VideoWriter(tmp_path / "discarded.mp4", 320, 240, 30) as writer:
            writer.write(frame)
            raise RuntimeError("the block failed")
    assert not (tmp_path / "discarded.mp4").exists()
    writer = ar.VideoWriter(tmp_path / "sized.avi", 320, 240, 30)
    with pytest.raises(ValueError, match="320 × 240"):
        writer.write(np.zeros((100, 100, 3), np.uint8))
    writer.write(frame.image)
    writer.finish()
    with pytest.raises(ValueError, match="finished"):
        writer.write(frame)
    video = ar.open_video(tmp_path / "sized.avi")
    assert len(list(video)) == 1 and video.read() is None
    with pytest.raises(FileNotFoundError, match="missing.mp4"):
        ar.open_video(tmp_path / "missing.mp4")
    pictures = ar.open_pictures(charuco_photos()[:2], fps=2)
    assert [(f.index, f.time) for f in pictures] == [(0, 0.0), (1, 0.5)]
    with pytest.raises(ValueError, match="distances"):
        small_scene(10, nearest=0.7, farthest=0.5)


def test_the_live_probe_finds_the_mirror_ball_in_a_real_photo():
    photo = ar.read_picture(vision("mirrorball/room.jpg")).image  # 4096 × 4096, the ball cropped tight
    k = 4
    small = photo.reshape(photo.shape[0] // k, k, photo.shape[1] // k, k, 3).mean(axis=(1, 3)).round().astype(np.uint8)
    probe = ar.LiveProbe()
    assert not probe.has_light and probe.light.shape == (3, 0)
    assert probe.update(small), probe.ball.reason
    x, y, r = probe.ball.circle
    top, bottom, left, right = 71, 62, 62, 74  # mirrorball_params.json's hand-tuned crop
    width, height = photo.shape[1] - left - right, photo.shape[0] - top - bottom
    assert np.hypot(x - (left + width / 2) / k, y - (top + height / 2) / k) < 3.0
    assert r == pytest.approx((width + height) / 4 / k, rel=0.01)
    light = probe.light
    assert light.shape == (3, 36) and np.all(light[:, 0] > 0) and np.all(np.isfinite(light))
    assert probe.picture.shape == (128, 128, 4) and probe.picture.dtype == np.uint8
    assert probe.probe_image.shape == (128, 128, 3)
    assert probe.probe().layout == thespis.lighting.ProbeLayout.MIRRORBALL
    with pytest.raises(ValueError, match="order"):
        ar.LiveProbe(order=0)
    given = ar.LiveProbe(circle=(x, y, r), order=3)
    assert given.update(ar.VideoFrame(small)) and given.light.shape == (3, 9)


def test_a_printed_picture_is_tracked_where_it_fills_the_frame():
    graf = vision("features/graf1.png")
    frame = ar.read_picture(graf)
    camera = ar.CameraIntrinsics(frame.width, frame.height, fx=800.0)
    tracker = ar.make_tracker(camera, picture=graf, width=0.3)
    assert tracker.markers == [] and tracker.charuco_corners is None
    estimate = tracker.estimate(frame)
    # Seen face-on filling the 800 px frame at f = 800 px, a 0.3 m print is 0.3 m away, its top-left
    # corner (the target's origin) half a width left and half a height up.
    assert estimate.found and estimate.features >= 40
    np.testing.assert_allclose(estimate.pose.tvec, [-0.15, -0.12, 0.3], atol=0.002)
    np.testing.assert_allclose(tracker.corners, [[0, 0], [800, 0], [800, 640], [0, 640]], atol=1.5)
    result = ar.track(pictures=[graf, graf], camera=camera, target=graf, width=0.3)
    assert all(f.tracked for f in result) and "graf1.png" in result.tracker
    with pytest.raises(ValueError, match="printed width of graf1.png"):
        ar.make_tracker(camera, picture=graf)
