/*
 * The calm scenes of the reference tests, one per mapping row of docs/format.md: each is
 * built by an adapter and, in fidelity_24_test.cpp (Box2D 2.4) and box2d3_fidelity.c (v3),
 * by hand through the engine's own API from what the file means; the two worlds must agree
 * bit for bit at steps 60 and 600, but for the bodies the adapter names in a report. The
 * same scenes go through both engines in fidelity_24_vs_v3, compared within a tolerance.
 * Plain C, for every one of those tests. Gravity is (0, -10) unless a scene says.
 */
#ifndef BOX2SCENE_FIDELITY_SCENES_H
#define BOX2SCENE_FIDELITY_SCENES_H

#include <string.h>

#define FIDELITY_BOX                                                                         \
    "<Shape Type=\"Polygon\"><Vertices><Vertex>-0.5 -0.5</Vertex><Vertex>0.5 -0.5</Vertex>" \
    "<Vertex>0.5 0.5</Vertex><Vertex>-0.5 0.5</Vertex></Vertices></Shape>"
#define FIDELITY_GROUND \
    "<Shape Type=\"Polygon\"><Vertices><Vertex>-20 0</Vertex><Vertex>20 0</Vertex></Vertices></Shape>"
#define FIDELITY_BALL "<Shape Type=\"Circle\"><Radius>0.5</Radius><Position>0 0</Position></Shape>"

typedef struct fidelity_scene {
    const char* name;
    const char* xml;
} fidelity_scene;

static const fidelity_scene fidelity_scenes[] = {
    {"body_fields",
     "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>" FIDELITY_BOX FIDELITY_GROUND
     "</Shapes><Fixtures>"
     "<Fixture><Shape>0</Shape><Density>2</Density><Friction>0.4</Friction>"
     "<Restitution>0.1</Restitution></Fixture>"
     "<Fixture><Shape>1</Shape><Friction>0.6</Friction></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Static\"><Fixtures><ID>1</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>-3 4</Position><Angle>0.3</Angle>"
     "<LinearVelocity>1 2</LinearVelocity><AngularVelocity>-1.5</AngularVelocity>"
     "<LinearDamping>0.1</LinearDamping><AngularDamping>0.2</AngularDamping>"
     "<GravityScale>0.5</GravityScale><Bullet>true</Bullet><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>0 3</Position><Angle>0.2</Angle>"
     "<FixedRotation>true</FixedRotation><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Kinematic\"><Position>3 2</Position><LinearVelocity>0.5 0</LinearVelocity>"
     "<AngularVelocity>0.8</AngularVelocity><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>6 5</Position><Active>false</Active>"
     "<Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>-6 0.5</Position><Awake>false</Awake>"
     "<Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>9 3</Position><Awake>false</Awake>"
     "<AllowSleep>false</AllowSleep><Fixtures><ID>0</ID></Fixtures></Body>"
     "</Bodies><Joints/></World>"},
    {"mass_data",
     "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>" FIDELITY_BOX FIDELITY_GROUND
     FIDELITY_BALL "</Shapes><Fixtures>"
     "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>"
     "<Fixture><Shape>1</Shape></Fixture>"
     "<Fixture><Shape>2</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Static\"><Fixtures><ID>1</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>-4 3</Position><MassData><Mass>3</Mass>"
     "<Center>0.1 0</Center><Inertia>2</Inertia></MassData><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>-1 6</Position><AngularVelocity>3</AngularVelocity>"
     "<MassData><Center>0.3 0</Center></MassData><Fixtures><ID>2</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>2 6</Position><MassData><Mass>0</Mass>"
     "<Center>0.4 0</Center><Inertia>0.8</Inertia></MassData><Fixtures><ID>2</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>5 3</Position><Angle>0.4</Angle><MassData>"
     "<Inertia>0.5</Inertia></MassData><Fixtures><ID>0</ID></Fixtures></Body>"
     "</Bodies><Joints><Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>3</BodyB>"
     "<LocalAnchorA>2 6</LocalAnchorA></Joint></Joints></World>"},
    {"shapes",
     "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>"
     "<Shape Type=\"Circle\"><Radius>0.4</Radius><Position>0.1 0</Position></Shape>"
     "<Shape Type=\"Polygon\"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex>"
     "<Vertex>0.3 0.8</Vertex></Vertices></Shape>" FIDELITY_GROUND
     "<Shape Type=\"Edge\"><Vertex1>-8 4</Vertex1><Vertex2>-2 2</Vertex2></Shape>"
     "<Shape Type=\"Chain\"><Vertices><Vertex>4 3</Vertex><Vertex>7 1.5</Vertex>"
     "<Vertex>10 3</Vertex></Vertices></Shape>"
     "<Shape Type=\"Polygon\"><Vertices><Vertex>0.6 0</Vertex><Vertex>0.3 0.52</Vertex>"
     "<Vertex>-0.3 0.52</Vertex><Vertex>-0.6 0</Vertex><Vertex>-0.3 -0.52</Vertex>"
     "<Vertex>0.3 -0.52</Vertex></Vertices><Centroid>0.05 0</Centroid></Shape>"
     "<Shape Type=\"Circle\"><Radius>0.3</Radius><Position>0 0</Position></Shape>"
     "</Shapes><Fixtures>"
     "<Fixture><Shape>0</Shape><Density>1</Density><Friction>0.3</Friction><FilterData>"
     "<CategoryBits>2</CategoryBits><MaskBits>65533</MaskBits><GroupIndex>-1</GroupIndex>"
     "</FilterData></Fixture>"
     "<Fixture><Shape>1</Shape><Density>2</Density><Restitution>0.2</Restitution></Fixture>"
     "<Fixture><Shape>2</Shape><Friction>0.8</Friction></Fixture>"
     "<Fixture><Shape>3</Shape></Fixture><Fixture><Shape>4</Shape></Fixture>"
     "<Fixture><Shape>5</Shape><Density>1</Density></Fixture>"
     "<Fixture><Shape>6</Shape><IsSensor>true</IsSensor></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Static\"><Fixtures><ID>2</ID><ID>3</ID><ID>4</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>-6 6</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>-5.5 8</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>6.5 5</Position><Fixtures><ID>1</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>1 4</Position><Fixtures><ID>5</ID></Fixtures></Body>"
     "<Body Type=\"Static\"><Position>1 1</Position><Fixtures><ID>6</ID></Fixtures></Body>"
     "</Bodies><Joints/></World>"},
    {"revolute",
     "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>"
     "<Shape Type=\"Polygon\"><Vertices><Vertex>-1 -0.1</Vertex><Vertex>1 -0.1</Vertex>"
     "<Vertex>1 0.1</Vertex><Vertex>-1 0.1</Vertex></Vertices></Shape>"
     "</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Static\"/>"
     "<Body Type=\"Dynamic\"><Position>1 5</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>5 5</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "</Bodies><Joints>"
     "<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 5</LocalAnchorA>"
     "<LocalAnchorB>-1 0</LocalAnchorB><ReferenceAngle>0.2</ReferenceAngle>"
     "<EnableLimit>true</EnableLimit><LowerAngle>-0.5</LowerAngle><UpperAngle>0.6</UpperAngle>"
     "</Joint>"
     "<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>5 5</LocalAnchorA>"
     "<EnableMotor>true</EnableMotor><MotorSpeed>2</MotorSpeed><MaxMotorTorque>50</MaxMotorTorque>"
     "</Joint></Joints></World>"},
    {"prismatic",
     "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>" FIDELITY_BOX
     "</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Static\"/>"
     "<Body Type=\"Dynamic\"><Position>0 3</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Static\"><Position>5 0</Position><Angle>0.5</Angle></Body>"
     "<Body Type=\"Dynamic\"><Position>5 3</Position><Angle>0.6</Angle>"
     "<Fixtures><ID>0</ID></Fixtures></Body>"
     "</Bodies><Joints>"
     "<Joint Type=\"Prismatic\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 3</LocalAnchorA>"
     "<LocalAxisA>1 1</LocalAxisA><EnableLimit>true</EnableLimit><LowerTranslation>-1</LowerTranslation>"
     "<UpperTranslation>1.5</UpperTranslation><EnableMotor>true</EnableMotor>"
     "<MaxMotorForce>30</MaxMotorForce><MotorSpeed>2</MotorSpeed></Joint>"
     "<Joint Type=\"Prismatic\"><BodyA>2</BodyA><BodyB>3</BodyB>"
     "<LocalAnchorA>1.43827662 2.63274789</LocalAnchorA><LocalAxisA>0 1</LocalAxisA>"
     "<ReferenceAngle>0.1</ReferenceAngle><EnableLimit>true</EnableLimit>"
     "<LowerTranslation>-2</LowerTranslation><UpperTranslation>1</UpperTranslation></Joint>"
     "</Joints></World>"},
    {"distance",
     "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>" FIDELITY_BALL
     "</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Static\"/>"
     "<Body Type=\"Dynamic\"><Position>3 5</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>6 3</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "</Bodies><Joints>"
     "<Joint Type=\"Distance\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 5</LocalAnchorA>"
     "<Length>3</Length></Joint>"
     "<Joint Type=\"Distance\"><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>6 6</LocalAnchorA>"
     "<Length>2</Length><FrequencyHz>2</FrequencyHz><DampingRatio>0.3</DampingRatio></Joint>"
     "</Joints></World>"},
    {"rope",
     "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>" FIDELITY_BOX
     "</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Static\"/>"
     "<Body Type=\"Dynamic\"><Position>2 5</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "</Bodies><Joints>"
     "<Joint Type=\"Rope\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 5</LocalAnchorA>"
     "<LocalAnchorB>0 0</LocalAnchorB><MaxLength>3</MaxLength></Joint></Joints></World>"},
    {"line",
     "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>" FIDELITY_BOX
     "</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Static\"/>"
     "<Body Type=\"Dynamic\"><Position>0 2</Position><LinearVelocity>3 0</LinearVelocity>"
     "<Fixtures><ID>0</ID></Fixtures></Body>"
     "</Bodies><Joints>"
     "<Joint Type=\"Line\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 2</LocalAnchorA>"
     "<LocalAxisA>1 0</LocalAxisA><EnableLimit>true</EnableLimit>"
     "<LowerTranslation>-1</LowerTranslation><UpperTranslation>2</UpperTranslation></Joint>"
     "</Joints></World>"},
    {"wheel",
     "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>" FIDELITY_GROUND
     "<Shape Type=\"Polygon\"><Vertices><Vertex>-2 -0.25</Vertex><Vertex>2 -0.25</Vertex>"
     "<Vertex>2 0.25</Vertex><Vertex>-2 0.25</Vertex></Vertices></Shape>"
     "<Shape Type=\"Circle\"><Radius>0.4</Radius><Position>0 0</Position></Shape>"
     "</Shapes><Fixtures><Fixture><Shape>0</Shape><Friction>0.9</Friction></Fixture>"
     "<Fixture><Shape>1</Shape><Density>1</Density></Fixture>"
     "<Fixture><Shape>2</Shape><Density>1</Density><Friction>0.9</Friction></Fixture>"
     "</Fixtures><Bodies>"
     "<Body Type=\"Static\"><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>0 1.2</Position><Fixtures><ID>1</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>-1.5 0.4</Position><Fixtures><ID>2</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>1.5 0.4</Position><Fixtures><ID>2</ID></Fixtures></Body>"
     "</Bodies><Joints>"
     "<Joint Type=\"Wheel\"><BodyA>1</BodyA><BodyB>2</BodyB><LocalAnchorA>-1.5 -0.8</LocalAnchorA>"
     "<LocalAxisA>0 1</LocalAxisA><EnableMotor>true</EnableMotor><MaxMotorTorque>20</MaxMotorTorque>"
     "<MotorSpeed>-5</MotorSpeed><FrequencyHz>2</FrequencyHz><DampingRatio>0.7</DampingRatio></Joint>"
     "<Joint Type=\"Wheel\"><BodyA>1</BodyA><BodyB>3</BodyB><LocalAnchorA>1.5 -0.8</LocalAnchorA>"
     "<LocalAxisA>0 1</LocalAxisA><FrequencyHz>3</FrequencyHz><DampingRatio>0.5</DampingRatio>"
     "</Joint></Joints></World>"},
    {"weld",
     "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>"
     "<Shape Type=\"Polygon\"><Vertices><Vertex>0 -0.1</Vertex><Vertex>2 -0.1</Vertex>"
     "<Vertex>2 0.1</Vertex><Vertex>0 0.1</Vertex></Vertices></Shape>"
     "</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Static\"/>"
     "<Body Type=\"Dynamic\"><Position>0 5</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>0 2</Position><Angle>0.1</Angle>"
     "<Fixtures><ID>0</ID></Fixtures></Body>"
     "</Bodies><Joints>"
     "<Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 5</LocalAnchorA>"
     "<FrequencyHz>1</FrequencyHz><DampingRatio>0.2</DampingRatio></Joint>"
     "<Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>0 2</LocalAnchorA>"
     "<ReferenceAngle>0.1</ReferenceAngle></Joint></Joints></World>"},
    {"friction",
     "<World Version=\"2\"><Gravity>0 0</Gravity><Shapes>" FIDELITY_BOX
     "</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Static\"/>"
     "<Body Type=\"Dynamic\"><LinearVelocity>4 1</LinearVelocity><AngularVelocity>3</AngularVelocity>"
     "<Fixtures><ID>0</ID></Fixtures></Body>"
     "</Bodies><Joints>"
     "<Joint Type=\"Friction\"><BodyA>0</BodyA><BodyB>1</BodyB><MaxForce>2</MaxForce>"
     "<MaxTorque>0.5</MaxTorque></Joint></Joints></World>"},
    {"motor",
     "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>" FIDELITY_BOX
     "</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Static\"><Angle>1</Angle></Body>"
     "<Body Type=\"Dynamic\"><Fixtures><ID>0</ID></Fixtures></Body>"
     "</Bodies><Joints>"
     "<Joint Type=\"Motor\"><BodyA>0</BodyA><BodyB>1</BodyB><LinearOffset>2 0</LinearOffset>"
     "<AngularOffset>0.5</AngularOffset><MaxForce>100</MaxForce><MaxTorque>50</MaxTorque>"
     "</Joint></Joints></World>"},
    {"turning_a",
     "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>" FIDELITY_BOX
     "</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Kinematic\"><AngularVelocity>0.5</AngularVelocity>"
     "<Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>2 0</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>0 3</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>-3 0</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "</Bodies><Joints>"
     "<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>2 0</LocalAnchorA>"
     "</Joint>"
     "<Joint Type=\"Prismatic\"><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>0 3</LocalAnchorA>"
     "<LocalAxisA>0 1</LocalAxisA><EnableLimit>true</EnableLimit>"
     "<LowerTranslation>-1</LowerTranslation><UpperTranslation>1</UpperTranslation></Joint>"
     "<Joint Type=\"Motor\"><BodyA>0</BodyA><BodyB>3</BodyB><LinearOffset>-3 0</LinearOffset>"
     "<MaxForce>200</MaxForce><MaxTorque>50</MaxTorque></Joint></Joints></World>"},
    {"pulley",
     "<World Version=\"1\"><Gravity>0 -10</Gravity><Shapes>" FIDELITY_BOX
     "</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>2</Density></Fixture>"
     "<Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Static\"/>"
     "<Body Type=\"Dynamic\"><Position>-2 3</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>2 4</Position><Fixtures><ID>1</ID></Fixtures></Body>"
     "</Bodies><Joints>"
     "<Joint Type=\"Pulley\"><BodyA>1</BodyA><BodyB>2</BodyB><GroundAnchorA>-2 8</GroundAnchorA>"
     "<GroundAnchorB>2 8</GroundAnchorB><LocalAnchorA>0 0</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB>"
     "<LengthA>5</LengthA><LengthB>4</LengthB><MaxLengthA>5.5</MaxLengthA><Ratio>1</Ratio>"
     "</Joint></Joints></World>"},
    {"gear",
     "<World Version=\"1\"><Gravity>0 -10</Gravity><Shapes>" FIDELITY_BALL
     "</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
     "<Body Type=\"Static\"/>"
     "<Body Type=\"Dynamic\"><Position>0 3</Position><AngularVelocity>2</AngularVelocity>"
     "<Fixtures><ID>0</ID></Fixtures></Body>"
     "<Body Type=\"Dynamic\"><Position>3 3</Position><Fixtures><ID>0</ID></Fixtures></Body>"
     "</Bodies><Joints>"
     "<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 3</LocalAnchorA></Joint>"
     "<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>3 3</LocalAnchorA></Joint>"
     "<Joint Type=\"Gear\"><BodyA>1</BodyA><BodyB>2</BodyB><JointA>0</JointA><JointB>1</JointB>"
     "<Ratio>2</Ratio></Joint></Joints></World>"},
};

#define FIDELITY_SCENE_COUNT (sizeof fidelity_scenes / sizeof fidelity_scenes[0])

/* The scene named `name`, or NULL. */
static inline const fidelity_scene* fidelity_scene_named(const char* name) {
    for (size_t i = 0; i < FIDELITY_SCENE_COUNT; ++i) {
        if (strcmp(fidelity_scenes[i].name, name) == 0) {
            return &fidelity_scenes[i];
        }
    }
    return NULL;
}

#endif /* BOX2SCENE_FIDELITY_SCENES_H */
