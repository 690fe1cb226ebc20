// Small scenes, loaded with b2s_load_memory and built with the adapter, that must behave as
// their joints and mass data say: "build a world, step it, check the positions".
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <algorithm>
#include <cmath>

#include "test_macros.h"
#include "test_worlds.hpp"

static int revolute_pendulum_keeps_its_radius() {
    World w(R"(<World Version="1">
      <Shapes><Shape Type="Circle"><Radius>0.25</Radius><Position>0 0</Position></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Static"><Position>0 10</Position></Body>
        <Body Type="Dynamic"><Position>5 10</Position><Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints>
        <Joint Type="Revolute"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorB>-5 0</LocalAnchorB></Joint>
      </Joints>
    </World>)");
    ENSURE(w.ok());
    b2Vec2 pivot(0.0f, 10.0f);
    b2Body* bob = w.body(1);
    float lowest = bob->GetPosition().y;
    ENSURE(holds_for_steps(w.world, 120, [&] {
        lowest = std::min(lowest, bob->GetPosition().y);
        return std::fabs(b2Distance(pivot, bob->GetPosition()) - 5.0f) < 0.05f;
    }));
    ENSURE(lowest < 5.5f); // it swung through the bottom
    return 0;
}

static int rigid_distance_joint_keeps_its_length() {
    // Falling straight away from its anchor: a slack 2.4 distance joint (stiffness 0 with
    // the default min/max, the classic porting bug) would let it go.
    World w(R"(<World Version="1">
      <Shapes><Shape Type="Circle"><Radius>0.25</Radius><Position>0 0</Position></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Static"><Position>0 10</Position></Body>
        <Body Type="Dynamic"><Position>3 10</Position><LinearVelocity>0 -4</LinearVelocity>
          <Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints>
        <Joint Type="Distance"><BodyA>0</BodyA><BodyB>1</BodyB><Length>3</Length></Joint>
      </Joints>
    </World>)");
    ENSURE(w.ok());
    b2Body* end = w.body(1);
    float lowest = end->GetPosition().y;
    ENSURE(holds_for_steps(w.world, 120, [&] {
        lowest = std::min(lowest, end->GetPosition().y);
        return std::fabs(b2Distance(b2Vec2(0.0f, 10.0f), end->GetPosition()) - 3.0f) < 0.03f;
    }));
    ENSURE(lowest < 7.5f); // it swung through the bottom
    return 0;
}

static int prismatic_body_stays_on_its_axis() {
    World w(R"(<World Version="1">
      <Shapes><Shape Type="Circle"><Radius>0.25</Radius><Position>0 0</Position></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Static" />
        <Body Type="Dynamic"><Position>2 5</Position><AngularVelocity>3</AngularVelocity>
          <Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints>
        <Joint Type="Prismatic"><BodyA>0</BodyA><BodyB>1</BodyB>
          <LocalAnchorA>2 5</LocalAnchorA><LocalAxisA>1 1</LocalAxisA></Joint>
      </Joints>
    </World>)");
    ENSURE(w.ok());
    b2Body* slider = w.body(1);
    b2Vec2 origin(2.0f, 5.0f);
    b2Vec2 axis(1.0f, 1.0f);
    axis.Normalize();
    ENSURE(holds_for_steps(w.world, 120, [&] {
        b2Vec2 moved = slider->GetPosition() - origin;
        return std::fabs(b2Cross(moved, axis)) < 0.01f && std::fabs(slider->GetAngle()) < 0.01f;
    }));
    ENSURE(b2Dot(slider->GetPosition() - origin, axis) < -1.0f); // it slid down the axis
    return 0;
}

static int pulley_keeps_its_total_length() {
    World w(R"(<World Version="1">
      <Shapes><Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes>
      <Fixtures>
        <Fixture><Shape>0</Shape><Density>2.5</Density></Fixture>
        <Fixture><Shape>0</Shape><Density>1</Density></Fixture>
      </Fixtures>
      <Bodies>
        <Body Type="Dynamic"><Position>-2 5</Position><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>2 6</Position><Fixtures><ID>1</ID></Fixtures></Body>
      </Bodies>
      <Joints>
        <Joint Type="Pulley"><BodyA>0</BodyA><BodyB>1</BodyB>
          <GroundAnchorA>-2 10</GroundAnchorA><GroundAnchorB>2 10</GroundAnchorB>
          <LocalAnchorA>0 0</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB>
          <LengthA>5</LengthA><LengthB>4</LengthB><Ratio>2</Ratio></Joint>
      </Joints>
    </World>)");
    ENSURE(w.ok());
    auto* pulley = static_cast<b2PulleyJoint*>(w.joint(0));
    ENSURE_FLOAT(pulley->GetRatio(), 2.0f);
    ENSURE(!pulley->GetCollideConnected());
    ENSURE(holds_for_steps(w.world, 120, [&] {
        float total = pulley->GetCurrentLengthA() + 2.0f * pulley->GetCurrentLengthB();
        return std::fabs(total - 13.0f) < 0.13f;
    }));
    ENSURE(std::fabs(pulley->GetCurrentLengthA() - 5.0f) > 0.5f); // it moved
    return 0;
}

static int weld_keeps_its_relative_angle() {
    // B sits at A's anchor (1, 0), turned by the reference angle 0.3.
    World w(R"(<World Version="1">
      <Shapes><Shape Type="Polygon"><Vertices>
        <Vertex>-1 -0.2</Vertex><Vertex>1 -0.2</Vertex><Vertex>1 0.2</Vertex><Vertex>-1 0.2</Vertex>
      </Vertices></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Dynamic"><Position>0 5</Position><AngularVelocity>2</AngularVelocity>
          <Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>1.955336489 5.295520207</Position><Angle>0.3</Angle>
          <Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints>
        <Joint Type="Weld"><BodyA>0</BodyA><BodyB>1</BodyB>
          <LocalAnchorA>1 0</LocalAnchorA><LocalAnchorB>-1 0</LocalAnchorB>
          <ReferenceAngle>0.3</ReferenceAngle></Joint>
      </Joints>
    </World>)");
    ENSURE(w.ok());
    b2Body* a = w.body(0);
    b2Body* b = w.body(1);
    ENSURE(holds_for_steps(w.world, 120, [&] {
        return std::fabs(b->GetAngle() - a->GetAngle() - 0.3f) < 0.01f;
    }));
    ENSURE(std::fabs(a->GetAngle()) > 0.5f); // the pair turned
    return 0;
}

static int gear_keeps_its_ratio() {
    // Box2D 2.4's gear constraint: coordinate1 + ratio * coordinate2 stays constant, where a
    // revolute joint's coordinate is its joint angle.
    World w(R"(<World Version="1">
      <Gravity>0 0</Gravity>
      <Shapes>
        <Shape Type="Circle"><Radius>1</Radius><Position>0 0</Position></Shape>
        <Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape>
      </Shapes>
      <Fixtures>
        <Fixture><Shape>0</Shape><Density>1</Density></Fixture>
        <Fixture><Shape>1</Shape><Density>1</Density></Fixture>
      </Fixtures>
      <Bodies>
        <Body Type="Static" />
        <Body Type="Dynamic"><Position>0 5</Position><AngularVelocity>1</AngularVelocity>
          <Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>3 5</Position><Fixtures><ID>1</ID></Fixtures></Body>
      </Bodies>
      <Joints>
        <Joint Type="Revolute"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 5</LocalAnchorA></Joint>
        <Joint Type="Revolute"><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>3 5</LocalAnchorA></Joint>
        <Joint Type="Gear"><BodyA>1</BodyA><BodyB>2</BodyB>
          <JointA>0</JointA><JointB>1</JointB><Ratio>2</Ratio></Joint>
      </Joints>
    </World>)");
    ENSURE(w.ok());
    auto* first = static_cast<b2RevoluteJoint*>(w.joint(0));
    auto* second = static_cast<b2RevoluteJoint*>(w.joint(1));
    auto* gear = static_cast<b2GearJoint*>(w.joint(2));
    ENSURE_EQ(gear->GetType(), e_gearJoint);
    ENSURE(gear->GetJoint1() == first && gear->GetJoint2() == second);
    ENSURE_FLOAT(gear->GetRatio(), 2.0f);
    ENSURE(holds_for_steps(w.world, 120, [&] {
        return std::fabs(first->GetJointAngle() + 2.0f * second->GetJointAngle()) < 1e-3f;
    }));
    ENSURE(std::fabs(first->GetJointAngle()) > 0.2f); // they turned
    return 0;
}

static int mass_data_overrides_only_what_it_gives() {
    // A circle centred on the body origin: Box2D computes centre (0, 0) exactly, so a
    // kept datum must come out exactly as computed.
    World w(R"(<World Version="1">
      <Shapes><Shape Type="Circle"><Radius>1</Radius><Position>0 0</Position></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Dynamic"><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>5 0</Position><Fixtures><ID>0</ID></Fixtures>
          <MassData><Mass>2</Mass><Center>0.5 0.25</Center><Inertia>3</Inertia></MassData></Body>
        <Body Type="Dynamic"><Position>10 0</Position><Fixtures><ID>0</ID></Fixtures>
          <MassData><Mass>2</Mass></MassData></Body>
        <Body Type="Dynamic"><Position>15 0</Position><Fixtures><ID>0</ID></Fixtures>
          <MassData><Center>0.5 0</Center></MassData></Body>
        <Body Type="Dynamic"><Position>20 0</Position><Fixtures><ID>0</ID></Fixtures>
          <MassData><Inertia>3</Inertia></MassData></Body>
      </Bodies>
      <Joints />
    </World>)");
    ENSURE(w.ok());
    const b2Body* twin = w.body(0);
    const b2Body* all = w.body(1);
    const b2Body* mass_only = w.body(2);
    const b2Body* center_only = w.body(3);
    const b2Body* inertia_only = w.body(4);

    // Every datum given: exactly those (the values keep Box2D's arithmetic exact).
    ENSURE_FLOAT(all->GetMass(), 2.0f);
    ENSURE_FLOAT(all->GetLocalCenter().x, 0.5f);
    ENSURE_FLOAT(all->GetLocalCenter().y, 0.25f);
    ENSURE_FLOAT(all->GetInertia(), 3.0f);

    ENSURE_FLOAT(mass_only->GetMass(), 2.0f);
    ENSURE_FLOAT(mass_only->GetLocalCenter().x, twin->GetLocalCenter().x);
    ENSURE_FLOAT(mass_only->GetLocalCenter().y, twin->GetLocalCenter().y);
    ENSURE_FLOAT(mass_only->GetInertia(), twin->GetInertia());

    // Moving the centre changes the inertia about it, not the one about the origin (which
    // Box2D rounds through the central inertia: hence "near").
    ENSURE_FLOAT(center_only->GetMass(), twin->GetMass());
    ENSURE_FLOAT(center_only->GetLocalCenter().x, 0.5f);
    ENSURE_FLOAT(center_only->GetLocalCenter().y, 0.0f);
    ENSURE_NEAR(center_only->GetInertia(), twin->GetInertia(), 1e-6 * twin->GetInertia());

    ENSURE_FLOAT(inertia_only->GetMass(), twin->GetMass());
    ENSURE_FLOAT(inertia_only->GetLocalCenter().x, twin->GetLocalCenter().x);
    ENSURE_FLOAT(inertia_only->GetInertia(), 3.0f);
    return 0;
}

static int given_centroid_lands_in_the_polygon() {
    World w(R"(<World Version="1">
      <Shapes>
        <Shape Type="Polygon"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>0 1</Vertex></Vertices>
          <Centroid>0.1 0.2</Centroid></Shape>
        <Shape Type="Polygon"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>0 1</Vertex></Vertices></Shape>
      </Shapes>
      <Fixtures><Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape></Fixture></Fixtures>
      <Bodies><Body Type="Static"><Fixtures><ID>0</ID><ID>1</ID></Fixtures></Body></Bodies>
      <Joints />
    </World>)");
    ENSURE(w.ok());
    ENSURE_EQ(w.built.fixtures[0]->GetType(), b2Shape::e_polygon);
    auto* given = static_cast<b2PolygonShape*>(w.built.fixtures[0]->GetShape());
    ENSURE_FLOAT(given->m_centroid.x, 0.1f);
    ENSURE_FLOAT(given->m_centroid.y, 0.2f);
    ENSURE_EQ(given->m_count, 3);

    // Absent is not (0, 0): the centroid stays Box2D's own.
    const b2Vec2 points[] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}};
    b2PolygonShape computed;
    computed.Set(points, 3);
    auto* absent = static_cast<b2PolygonShape*>(w.built.fixtures[1]->GetShape());
    ENSURE_FLOAT(absent->m_centroid.x, computed.m_centroid.x);
    ENSURE_FLOAT(absent->m_centroid.y, computed.m_centroid.y);
    ENSURE(absent->m_centroid.x != 0.0f);
    return 0;
}

static int two_vertex_polygon_becomes_an_edge() {
    World w(R"(<World Version="1">
      <Shapes><Shape Type="Polygon"><Vertices><Vertex>-3 1</Vertex><Vertex>4 2</Vertex></Vertices>
        <Centroid>0 0</Centroid></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Friction>0.5</Friction></Fixture></Fixtures>
      <Bodies><Body Type="Static"><Fixtures><ID>0</ID></Fixtures></Body></Bodies>
      <Joints />
    </World>)");
    ENSURE(w.ok());
    b2Fixture* fixture = w.built.fixtures[0];
    ENSURE_EQ(fixture->GetType(), b2Shape::e_edge);
    auto* edge = static_cast<b2EdgeShape*>(fixture->GetShape());
    ENSURE_FLOAT(edge->m_vertex1.x, -3.0f);
    ENSURE_FLOAT(edge->m_vertex1.y, 1.0f);
    ENSURE_FLOAT(edge->m_vertex2.x, 4.0f);
    ENSURE_FLOAT(edge->m_vertex2.y, 2.0f);
    ENSURE(!edge->m_oneSided);
    ENSURE_FLOAT(fixture->GetFriction(), 0.5f);
    return 0;
}

int main() {
    int failed = 0;
    failed += RUN_TEST(revolute_pendulum_keeps_its_radius);
    failed += RUN_TEST(rigid_distance_joint_keeps_its_length);
    failed += RUN_TEST(prismatic_body_stays_on_its_axis);
    failed += RUN_TEST(pulley_keeps_its_total_length);
    failed += RUN_TEST(weld_keeps_its_relative_angle);
    failed += RUN_TEST(gear_keeps_its_ratio);
    failed += RUN_TEST(mass_data_overrides_only_what_it_gives);
    failed += RUN_TEST(given_centroid_lands_in_the_polygon);
    failed += RUN_TEST(two_vertex_polygon_becomes_an_edge);
    return failed;
}
