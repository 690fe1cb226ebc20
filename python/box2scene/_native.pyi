"""Type hints of the extension module: the library's load, write and builder. The package's
modules wrap it; hosts use :func:`box2scene.load`, :class:`box2scene.Scene` and
:class:`box2scene.Builder`."""

from typing import Any, Dict, List, Optional, Sequence, Tuple

Vec2 = Tuple[float, float]

class NativeScene:
    def version(self) -> int: ...
    def gravity(self) -> Optional[Vec2]: ...
    def shapes(self) -> List[Dict[str, Any]]: ...
    def fixtures(self) -> List[Dict[str, Any]]: ...
    def bodies(self) -> List[Dict[str, Any]]: ...
    def joints(self) -> List[Dict[str, Any]]: ...
    def user_data(self) -> List[Dict[str, Any]]: ...
    def diagnostics(self) -> List[Dict[str, Any]]: ...
    def vertices(self) -> Tuple[Vec2, ...]: ...
    def fixture_ids(self) -> List[int]: ...
    def dialect(self) -> str: ...
    def to_xml(self, all_fields: bool, dialect: Optional[str] = None) -> str: ...
    def write(self, path: str, all_fields: bool, dialect: Optional[str] = None) -> None: ...
    def to_json(self) -> str: ...
    def columns(self, array: str) -> List[Tuple[str, str, int, bytes]]: ...
    def same_records(self, other: NativeScene) -> bool: ...
    def draw_svg(
        self,
        title: str,
        start: Optional[List[Tuple[float, float, float]]],
        end: Optional[List[Tuple[float, float, float]]],
        joints_created: Optional[List[bool]],
        trajectories: Sequence[Sequence[Sequence[float]]],
    ) -> str: ...

class NativeBuilder:
    def __init__(self) -> None: ...
    def set_gravity(self, gravity: Optional[Sequence[float]]) -> None: ...
    def add_user_data(self, raw: Optional[str] = None, type_name: Optional[str] = None, value: Optional[str] = None) -> int: ...
    def add_shape(self, record: Dict[str, Any]) -> int: ...
    def add_fixture(self, record: Dict[str, Any]) -> int: ...
    def add_body(self, record: Dict[str, Any]) -> int: ...
    def add_joint(self, record: Dict[str, Any]) -> int: ...
    @staticmethod
    def from_scene(scene: NativeScene) -> NativeBuilder: ...
    def replace_shape(self, index: int, record: Dict[str, Any]) -> None: ...
    def replace_fixture(self, index: int, record: Dict[str, Any]) -> None: ...
    def replace_body(self, index: int, record: Dict[str, Any]) -> None: ...
    def replace_joint(self, index: int, record: Dict[str, Any]) -> None: ...
    def remove_shape(self, index: int) -> None: ...
    def remove_fixture(self, index: int) -> None: ...
    def remove_body(self, index: int) -> None: ...
    def remove_joint(self, index: int) -> None: ...
    def finish(self) -> NativeScene: ...

def load_bytes(data: bytes, options: Dict[str, Any]) -> NativeScene: ...
def load_path(path: str, options: Dict[str, Any]) -> NativeScene: ...
def defaults(record: str, kind: Optional[str] = None) -> Dict[str, Any]: ...
def filter_widths() -> Tuple[int, int]: ...
def cosf(x: float) -> float: ...
def sinf(x: float) -> float: ...
def atan2f(y: float, x: float) -> float: ...
def nextafterf(x: float, toward: float) -> float: ...
def working_range(engine: str) -> Dict[str, Any]: ...
def world_gravity(scene: NativeScene, engine: str) -> Optional[Vec2]: ...

class NativePlanShape:
    slot: int
    fixture: int
    shape: int
    kind: str
    points: List[Vec2]
    center: Vec2
    radius: float
    density: float
    friction: float
    restitution: float
    category_bits: int
    mask_bits: int
    group_index: int
    is_sensor: bool
    name: Optional[str]
    fixture_is_sensor: bool

class NativePlanBody:
    body: int
    kind: int
    position: Vec2
    angle: float
    rotation: Vec2
    linear_velocity: Vec2
    angular_velocity: float
    linear_damping: float
    angular_damping: float
    gravity_scale: float
    name: Optional[str]
    shapes: Tuple[NativePlanShape, ...]
    mass: float
    center: Vec2
    inertia: float
    velocity_after_mass: Vec2
    allow_sleep: bool
    awake: bool
    fixed_rotation: bool
    bullet: bool
    enabled: bool
    apply_mass_from_shapes: bool
    set_mass: bool
    set_velocity: bool

class NativePlanJoint:
    joint: int
    name: Optional[str]
    kind: str
    body_a: int
    body_b: int
    joint_a: int
    joint_b: int
    anchor_a: Vec2
    anchor_b: Vec2
    axis: Vec2
    reference_angle: float
    ground_anchor_a: Vec2
    ground_anchor_b: Vec2
    length_a: float
    length_b: float
    ratio: float
    lower: float
    upper: float
    length: float
    min_length: float
    max_length: float
    motor_speed: float
    max_motor: float
    stiffness: float
    damping: float
    hertz: float
    damping_ratio: float
    linear_offset: Vec2
    angular_offset: float
    max_force: float
    max_torque: float
    correction_factor: float
    collide_connected: bool
    enable_limit: bool
    enable_motor: bool
    enable_spring: bool

class NativePlan:
    bodies: Tuple[NativePlanBody, ...]
    joints: Tuple[NativePlanJoint, ...]
    reports: Tuple[Tuple[str, str, int, Optional[str], str], ...]
    placed: bool
    body_count: int
    slot_count: int
    joint_count: int
    has_sensor: bool

def make_plan(
    scene: NativeScene,
    engine: str,
    gravity: Vec2,
    max_linear_speed: float = ...,
    placement: Tuple[Vec2, Vec2] = ...,
) -> NativePlan: ...

def capture(
    engine: str,
    gravity: Vec2,
    bodies: Sequence[Dict[str, Any]],
    joints: Sequence[Dict[str, Any]],
    skipped: Sequence[int] = ...,
    level: Optional[NativeScene] = ...,
) -> Tuple[NativeScene, List[Tuple[str, str, int, Optional[str], str]]]: ...
